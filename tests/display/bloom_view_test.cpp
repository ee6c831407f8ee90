// The bloom-only debug view (display/debug_views.h bloom_only_view) and the component it
// shows (display/bloom.h bloom_component): the component is exactly what apply_bloom adds
// beside what it removes, and the view shows it alone through the image's own pipeline.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/color/color_space.h"
#include "prism/display/bloom.h"
#include "prism/display/debug_views.h"

namespace prism::display {
namespace {

constexpr int kBloomImageSizePx = 128, kBloomSpotPx = 63;

// A dim 128² film with one bright 2×2 spot (in the exposed units of EV100 = −log2 1.2,
// whose exposure scale is 1).
ImageRgbF spot_film(float spot) {
  ImageRgbF img{kBloomImageSizePx, kBloomImageSizePx, std::vector<float>(3 * kBloomImageSizePx * kBloomImageSizePx, 0.05f)};
  for (int y = kBloomSpotPx; y <= kBloomSpotPx + 1; ++y)
    for (int x = kBloomSpotPx; x <= kBloomSpotPx + 1; ++x)
      for (int c = 0; c < 3; ++c) img.rgb[3 * (y * kBloomImageSizePx + x) + c] = spot;
  return img;
}

DisplaySettings unit_exposure() {
  DisplaySettings s;
  s.exposure_ev100 = -std::log2(1.2);
  return s;
}

TEST(BloomView, ComponentIsWhatApplyBloomAdds) {
  const ImageRgbF img = spot_film(50.0f);
  BloomSettings s;
  s.strength = 0.6;
  const ImageRgbF component = bloom_component(img, s);
  const ImageRgbF bright = bloom_bright_pass(img, s.threshold, s.threshold_space);
  const ImageRgbF bloomed = apply_bloom(img, s);
  for (std::size_t i = 0; i < img.rgb.size(); ++i)
    // float sums of the same terms in another order: a few ulps of values up to 50
    ASSERT_NEAR(bloomed.rgb[i], img.rgb[i] + component.rgb[i] - s.strength * bright.rgb[i], 2e-5) << i;
}

TEST(BloomView, ShowsTheHaloAloneThroughThePipeline) {
  const color::ColorSpace& space = color::color_space("srgb");
  DisplaySettings s = unit_exposure();
  s.bloom.strength = 0.5;
  const DisplayImage view = bloom_only_view(spot_film(50.0f), space, s);
  ASSERT_EQ(view.width, kBloomImageSizePx);
  // The dim background (0.05, below the threshold of 1) contributes nothing: far from the
  // spot the view is black (below 1e-6 of code: only the Gaussians' far tails reach there,
  // 1/4000 of an 8-bit step), while the image itself is not.
  const std::size_t corner = 3 * (2 * kBloomImageSizePx + 2);
  EXPECT_LT(view.code[corner], 1e-6f);
  EXPECT_GT(apply_display_pipeline(spot_film(50.0f), space, s).code[corner], 0.0f);
  // Around the spot the halo shows, fading outward.
  const auto at = [&](int x) { return view.nits[3 * (std::size_t(kBloomSpotPx) * kBloomImageSizePx + x) + 1]; };
  EXPECT_GT(at(kBloomSpotPx + 3), at(kBloomSpotPx + 12));
  EXPECT_GT(at(kBloomSpotPx + 12), 0.0f);
  // It is the component through the same pipeline at exposure scale 1.
  DisplaySettings plain = unit_exposure();
  const DisplayImage expected = apply_display_pipeline(bloom_component(spot_film(50.0f), s.bloom), space, plain);
  EXPECT_EQ(view.code, expected.code);
  // Bloom off: the view shows what strength 1 would spread.
  DisplaySettings off = unit_exposure();
  BloomSettings one = off.bloom;
  one.strength = 1.0;
  EXPECT_EQ(bloom_only_view(spot_film(50.0f), space, off).code,
            apply_display_pipeline(bloom_component(spot_film(50.0f), one), space, plain).code);
}

}  // namespace
}  // namespace prism::display
