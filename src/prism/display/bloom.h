#pragma once
// Bloom before tone mapping: light above the display's maximum luminance scatters into a
// wide halo, as veiling glare in a lens or eye does.
//
//   bright = the part of each pixel above the threshold (1.0 of the exposed image, which is
//            the max luminance 1.2·2^EV100 once exposure is applied — Lagarde & de
//            Rousiers 2014 §5.1):
//            hsv: V = max(R, G, B); bright = RGB · max(V − t, 0) / V   (hue and saturation kept)
//            rgb: bright_c = max(C − t, 0)                               (hue drifts to white)
//   halo   = Σ_k w_k · up(G_σ ∗ down^k(bright)), k = 0..levels−1, Σ w_k = 1 (a mip chain of
//            2×2 box downsamples, a separable Gaussian of σ = 1.5 px at each level, bilinear
//            upscale back), so each level spreads the light twice as far as the previous one.
//   out    = in + strength · (halo − bright)
// The last line moves a fraction `strength` of the above-threshold light into the halo
// instead of adding light: away from the borders the image's total energy is unchanged.
#include <string_view>

#include "prism/core/mat3.h"
#include "prism/io/image.h"

namespace prism::display {

enum class BloomThresholdSpace { hsv, rgb };

struct BloomSettings {
  double strength = 0.0;      // 0 = off (identity); in [0, 1]
  double threshold = 1.0;     // in exposed units: 1.0 = max luminance
  BloomThresholdSpace threshold_space = BloomThresholdSpace::hsv;
  int levels = 6;             // mip levels in the halo
};

// "hsv" or "rgb"; UsageError otherwise.
BloomThresholdSpace parse_bloom_threshold_space(std::string_view name);

// The above-threshold part of each pixel (the `bright` image above).
ImageRgbF bloom_bright_pass(const ImageRgbF& image, double threshold, BloomThresholdSpace space);

// The multi-scale blur of `bright` (the `halo` above), same size.
ImageRgbF bloom_halo(const ImageRgbF& bright, int levels);

// The light the stage spreads, strength · halo (the `bloom` debug view shows it alone);
// apply_bloom's output is image + component − strength · bright.
ImageRgbF bloom_component(const ImageRgbF& image, const BloomSettings& settings);

// The whole stage on an exposed scene-linear image. Strength 0 returns the input unchanged.
ImageRgbF apply_bloom(const ImageRgbF& image, const BloomSettings& settings);

// Exposure and bloom ahead of a display transform whose input matrix (from the film's
// space) is `to_input`. Bloom thresholds exposed values, so with bloom on, the film is
// exposed (non-finite samples become 0) and bloomed into `storage`, which the result then
// refers to; with bloom off, the exposure scale folds into `to_input` and the film itself is
// returned, untouched.
const ImageRgbF& expose_and_bloom(const ImageRgbF& film, double exposure_scale, const BloomSettings& bloom,
                                  ImageRgbF& storage, Mat3& to_input);

}  // namespace prism::display
