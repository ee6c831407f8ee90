// Render-scale upscale (display/resampling.h).
#include <gtest/gtest.h>

#include "prism/core/error.h"
#include "prism/display/resampling.h"

namespace prism::display {
namespace {

ImageRgbF ramp(int w, int h) {
  ImageRgbF img{w, h, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.rgb.push_back(static_cast<float>(x + 0.5 + 10 * c + 2 * (y + 0.5)));
  return img;
}

TEST(DisplayResampling, BilinearUpscaleReproducesLinearFunctions) {
  // f = x + 2y (+10c) sampled at pixel centres; bilinear interpolation is exact for it away
  // from the clamped border half-pixel.
  const ImageRgbF src = ramp(8, 6), up = upscale_bilinear(src, 16, 12);
  ASSERT_EQ(up.width, 16);
  ASSERT_EQ(up.height, 12);
  for (int y = 1; y < 11; ++y)
    for (int x = 1; x < 15; ++x)
      for (int c = 0; c < 3; ++c) {
        const double expected = (x + 0.5) / 2 + 10 * c + 2 * (y + 0.5) / 2;
        EXPECT_NEAR(up.rgb[3 * (y * 16 + x) + c], expected, 1e-5) << x << "," << y;
      }
}

TEST(DisplayResampling, UpscaleKeepsConstantsAndMean) {
  ImageRgbF flat{5, 3, std::vector<float>(45, 0.25f)};
  for (float v : upscale_bilinear(flat, 13, 7).rgb) EXPECT_FLOAT_EQ(v, 0.25f);
  // A 2× upscale keeps the mean exactly (each source pixel's weights sum to 4).
  const ImageRgbF src = ramp(6, 4), up = upscale_bilinear(src, 12, 8);
  double a = 0, b = 0;
  for (float v : src.rgb) a += v;
  for (float v : up.rgb) b += v;
  EXPECT_NEAR(b / 4, a, 1e-3);
}

TEST(DisplayResampling, RenderScaleSizes) {
  EXPECT_EQ(upscaled_size(320, 0.5), 640);
  EXPECT_EQ(upscaled_size(100, 1.0), 100);
  EXPECT_EQ(upscaled_size(213, 2.0 / 3.0), 320);
  EXPECT_THROW(upscaled_size(10, 0.0), UsageError);
  EXPECT_THROW(upscaled_size(10, 1.5), UsageError);
}

TEST(DisplayResampling, BoxDownsampleKeepsMean) {
  const ImageRgbF src = ramp(8, 6), down = downsample_box2(src);
  ASSERT_EQ(down.width, 4);
  double a = 0, b = 0;
  for (float v : src.rgb) a += v;
  for (float v : down.rgb) b += v;
  EXPECT_NEAR(b * 4, a, 1e-3);
}

}  // namespace
}  // namespace prism::display
