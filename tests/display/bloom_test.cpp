// Bloom (display/bloom.h): off is the identity, the halo keeps the energy it takes, and the
// HSV threshold keeps the bloom's hue where the per-channel threshold does not.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/core/error.h"
#include "prism/display/bloom.h"

namespace prism::display {
namespace {

// A dark 192×192 image with one bright saturated 2×2 spot in the middle.
constexpr int kN = 192, kC = 95;
ImageRgbF spot_image(float r, float g, float b) {
  ImageRgbF img{kN, kN, std::vector<float>(3 * kN * kN, 0.01f)};
  for (int y = kC; y <= kC + 1; ++y)
    for (int x = kC; x <= kC + 1; ++x) {
      float* p = &img.rgb[3 * (y * kN + x)];
      p[0] = r, p[1] = g, p[2] = b;
    }
  return img;
}

double channel_sum(const ImageRgbF& img, int c) {
  double s = 0;
  for (std::size_t i = c; i < img.rgb.size(); i += 3) s += img.rgb[i];
  return s;
}

TEST(DisplayBloom, OffIsIdentity) {
  const ImageRgbF img = spot_image(40, 10, 2);
  const ImageRgbF out = apply_bloom(img, BloomSettings{});
  EXPECT_EQ(out.rgb, img.rgb);
}

TEST(DisplayBloom, BelowThresholdIsUntouched) {
  ImageRgbF img = spot_image(0.9f, 0.5f, 0.2f);
  BloomSettings s;
  s.strength = 1.0;
  EXPECT_EQ(apply_bloom(img, s).rgb, img.rgb);
}

TEST(DisplayBloom, EnergyIsPreserved) {
  for (auto space : {BloomThresholdSpace::hsv, BloomThresholdSpace::rgb}) {
    const ImageRgbF img = spot_image(40, 10, 2);
    BloomSettings s;
    s.strength = 0.8;
    s.threshold_space = space;
    // 4 levels: the widest Gaussian (σ = 1.5 px at 1/8 size = 12 px, cut at 3σ = 36 px)
    // stays clear of the 95 px to the border, where the clamped gather would lose light.
    s.levels = 4;
    const ImageRgbF out = apply_bloom(img, s);
    for (int c = 0; c < 3; ++c) {
      // Box downsample and centred bilinear upsample keep the sum exactly, a normalised
      // Gaussian keeps it away from the borders; what is left is float accumulation over
      // 37k pixels (~1e-6 relative each).
      EXPECT_NEAR(channel_sum(out, c), channel_sum(img, c), 1e-4 * channel_sum(img, c)) << "channel " << c;
    }
    // Light did move: the spot lost energy, its neighbourhood gained.
    EXPECT_LT(out.rgb[3 * (kC * kN + kC)], img.rgb[3 * (kC * kN + kC)]);
    EXPECT_GT(out.rgb[3 * (kC * kN + kC + 9)], img.rgb[3 * (kC * kN + kC + 9)] + 1e-3f);
  }
}

TEST(DisplayBloom, HsvThresholdKeepsHue) {
  const ImageRgbF img = spot_image(40, 10, 2);
  const ImageRgbF halo = bloom_halo(bloom_bright_pass(img, 1.0, BloomThresholdSpace::hsv), 4);
  const ImageRgbF halo_rgb = bloom_halo(bloom_bright_pass(img, 1.0, BloomThresholdSpace::rgb), 4);
  // At several distances from the spot, the halo's R:G:B equals the source's 40:10:2.
  for (int dx : {3, 8, 20}) {
    const float* h = &halo.rgb[3 * (kC * kN + kC + dx)];
    EXPECT_NEAR(h[1] / h[0], 0.25, 1e-4) << dx;
    EXPECT_NEAR(h[2] / h[0], 0.05, 1e-4) << dx;
    // Per channel, (39, 9, 1): the halo is redder than the source.
    const float* q = &halo_rgb.rgb[3 * (kC * kN + kC + dx)];
    EXPECT_NEAR(q[1] / q[0], 9.0 / 39.0, 1e-4);
    EXPECT_GT(std::fabs(q[2] / q[0] - 0.05), 0.02);
  }
}

TEST(DisplayBloom, RejectsBadSettings) {
  const ImageRgbF img = spot_image(4, 1, 1);
  BloomSettings s;
  s.strength = 1.5;
  EXPECT_THROW(apply_bloom(img, s), UsageError);
  EXPECT_THROW(parse_bloom_threshold_space("lab"), UsageError);
  EXPECT_EQ(parse_bloom_threshold_space("RGB"), BloomThresholdSpace::rgb);
}

}  // namespace
}  // namespace prism::display
