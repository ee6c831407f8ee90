#include "prism/display/ui_overlay.h"

#include <algorithm>
#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"

namespace prism::display {

UiOverlay make_ui_overlay(const EncodedImage& rgba, double ui_nits, double blend_power) {
  if (rgba.channels != 4) throw UsageError("the overlay must be an RGBA PNG (it has " + std::to_string(rgba.channels) + " channels)");
  if (!(ui_nits >= 80.0 && ui_nits <= 300.0)) throw UsageError("--ui-nits must be in [80, 300]");
  if (!(blend_power > 0.0 && std::isfinite(blend_power))) throw UsageError("the UI blend power must be positive");
  UiOverlay o;
  o.width = rgba.width;
  o.height = rgba.height;
  o.ui_nits = ui_nits;
  o.blend_power = blend_power;
  const Mat3 to_ap1 = color::conversion_matrix(color::color_space("srgb"), color::color_space("acescg"),
                                               color::Cat::bradford);
  const double max_code = (1 << rgba.bit_depth) - 1;
  const std::size_t n = std::size_t(rgba.width) * rgba.height;
  o.ap1.resize(3 * n);
  o.alpha.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3d lin;
    for (int c = 0; c < 3; ++c) lin[c] = color::srgb_decode(rgba.samples[4 * i + c] / max_code);
    const Vec3d ap1 = to_ap1 * lin;
    for (int c = 0; c < 3; ++c) o.ap1[3 * i + c] = static_cast<float>(ap1[c]);
    o.alpha[i] = static_cast<float>(rgba.samples[4 * i + 3] / max_code);
  }
  return o;
}

UiComposite composite_ui(const Vec3d& bg, const Vec3d& ui, double alpha, double y_max, double ui_nits, double p) {
  const double a = std::clamp(alpha, 0.0, 1.0);
  const double w = y_max >= ui_nits ? std::pow(a, p) : std::pow(a, 1.0 / p);
  const double peak = y_max + w * (ui_nits - y_max);
  const double bg_scale = (1.0 - a) * std::min(1.0, y_max / peak);
  return {bg * bg_scale + ui * a, peak};
}

}  // namespace prism::display
