#pragma once
// Photographic exposure (Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based
// Rendering 3.0", §5.1): EV100 from camera settings, the saturation-based maximum
// luminance L_max = 78/(q·S)·2^EV100 = 1.2·2^EV100 for S = 100, q = 0.65 (ISO 12232), and
// the exposure scale 1/L_max that maps scene luminance in nits to relative film values.
#include <vector>

#include "prism/core/vec.h"

namespace prism::display {

// EV100 = log2(N² / t · 100 / S). Non-positive or non-finite input: UsageError.
double ev100_from_camera(double f_number, double shutter_s, double iso);

// 1.2 · 2^EV100 (nits). NaN or infinite EV100: UsageError.
double max_luminance_nits_from_ev100(double exposure_ev100);

// 1 / max luminance: the factor applied to scene-linear values.
double exposure_scale_from_ev100(double exposure_ev100);

// exp(mean(log(δ + Y))) over the pixels (Reinhard et al. 2002, eq. 1), Y = weights · rgb,
// δ = 1e-4 keeps black pixels finite. Empty image: 0.
double log_average_luminance(const std::vector<float>& rgb, const Vec3d& luminance_weights,
                             double delta = 1e-4);

// The EV100 whose exposure maps the log-average luminance to `key` (Reinhard's key value,
// 0.18 = ACES mid grey): scale·L_avg = key ⇔ EV100 = log2(L_avg / (1.2·key)).
double auto_exposure_ev100(double log_average_luminance, double key = 0.18);

}  // namespace prism::display
