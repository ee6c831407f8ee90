// Bilinear lookup of environment maps (scene/environment_lookup.h): the blend between
// texel centres, the neighbours across each mapping's borders (checked against the
// directions the mappings give), and the texel mean that the sampling density is built
// from (checked by integrating the lookup itself).
#include "prism/scene/environment_lookup.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "prism/scene/environment_mapping.h"

namespace prism {
namespace {

TextureImage rgb_map(int width, int height, const std::vector<float>& texels) {
  TextureImage t;
  t.name = "map";
  t.width = width;
  t.height = height;
  t.channels = 3;
  t.texels = texels;
  return t;
}

void expect_rgb(const Vec3f& got, const Vec3f& want) {
  // Weights of quarters, eighths and tenths of values below 10: a few float roundings.
  EXPECT_NEAR(got.x, want.x, 1e-6f);
  EXPECT_NEAR(got.y, want.y, 1e-6f);
  EXPECT_NEAR(got.z, want.z, 1e-6f);
}

TEST(EnvironmentLookup, TwoByOneMapBlendsBetweenTexelCentres) {
  // Texel centres at u = 1/4 (red) and u = 3/4 (blue); u is periodic in a lat-long map.
  const TextureImage map = rgb_map(2, 1, {1, 0, 0, 0, 0, 1});
  const auto at = [&](float u, float v) { return environment_radiance_bilinear(map, EnvironmentMapping::equirectangular, {u, v}); };
  expect_rgb(at(0.25f, 0.5f), {1, 0, 0});         // a texel centre: that texel alone
  expect_rgb(at(0.75f, 0.2f), {0, 0, 1});         // one row: v changes nothing
  expect_rgb(at(0.5f, 0.5f), {0.5f, 0, 0.5f});    // half way between the centres
  expect_rgb(at(0.375f, 0.9f), {0.75f, 0, 0.25f});
  expect_rgb(at(0.0f, 0.5f), {0.5f, 0, 0.5f});    // across the seam at φ = −π …
  expect_rgb(at(1.0f, 0.5f), {0.5f, 0, 0.5f});    // … the same as at φ = π
  expect_rgb(at(0.95f, 0.5f), {0.4f, 0, 0.6f});   // 0.2 texel past blue's centre towards red
}

TEST(EnvironmentLookup, RowsBlendAndClampAtThePoles) {
  const TextureImage map = rgb_map(1, 2, {2, 2, 2, 4, 4, 4});
  const auto at = [&](float v) { return environment_radiance_bilinear(map, EnvironmentMapping::equirectangular, {0.3f, v}).y; };
  EXPECT_FLOAT_EQ(at(0.5f), 3.0f);
  EXPECT_FLOAT_EQ(at(0.0f), 2.0f);  // above the first row's centre: that row
  EXPECT_FLOAT_EQ(at(1.0f), 4.0f);
  EXPECT_FLOAT_EQ(at(0.625f), 3.5f);
}

// The fold of the equal-area octahedral map: the texel just outside a border is the one
// inside it mirrored about the border's midpoint. Checked against the mapping itself:
// points just inside a border, mirrored so, are the same point of the sphere.
TEST(EnvironmentLookup, OctahedralBordersFoldAboutTheirMidpoints) {
  constexpr auto kMap = EnvironmentMapping::equal_area_octahedral;
  constexpr float kInside = 1e-4f;  // the directions then differ by O(1e-4) rad
  for (float t = 0.05f; t < 1.0f; t += 0.1f) {
    const auto d = [](float u, float v) { return environment_uv_to_direction(kMap, {u, v}); };
    EXPECT_LT(length(d(kInside, t) - d(kInside, 1.0f - t)), 1e-3f) << t;                       // left
    EXPECT_LT(length(d(1.0f - kInside, t) - d(1.0f - kInside, 1.0f - t)), 1e-3f) << t;         // right
    EXPECT_LT(length(d(t, kInside) - d(1.0f - t, kInside)), 1e-3f) << t;                       // top
    EXPECT_LT(length(d(t, 1.0f - kInside) - d(1.0f - t, 1.0f - kInside)), 1e-3f) << t;         // bottom
    // Not so across the middle of the map, where the fold would be wrong.
    EXPECT_GT(length(d(0.5f, t) - d(0.5f, 1.0f - t)), 1e-2f) << t;
  }
  constexpr int kW = 8, kH = 6;
  EXPECT_EQ(environment_texel_address(kMap, -1, 1, kW, kH), std::pair(0, 4));
  EXPECT_EQ(environment_texel_address(kMap, kW, 0, kW, kH), std::pair(kW - 1, kH - 1));
  EXPECT_EQ(environment_texel_address(kMap, 2, -1, kW, kH), std::pair(5, 0));
  EXPECT_EQ(environment_texel_address(kMap, 6, kH, kW, kH), std::pair(1, kH - 1));
  EXPECT_EQ(environment_texel_address(kMap, -1, -1, kW, kH), std::pair(kW - 1, kH - 1));  // the corners meet
  EXPECT_EQ(environment_texel_address(kMap, 3, 2, kW, kH), std::pair(3, 2));
}

TEST(EnvironmentLookup, EquirectangularNeighboursWrapInLongitude) {
  EXPECT_EQ(environment_texel_address(EnvironmentMapping::equirectangular, -1, 3, 8, 4), std::pair(7, 3));
  EXPECT_EQ(environment_texel_address(EnvironmentMapping::equirectangular, 8, 0, 8, 4), std::pair(0, 0));
  EXPECT_EQ(environment_texel_address(EnvironmentMapping::equirectangular, 2, -1, 8, 4), std::pair(2, 0));
  EXPECT_EQ(environment_texel_address(EnvironmentMapping::equirectangular, 2, 4, 8, 4), std::pair(2, 3));
}

// environment_texel_mean against the mean of the lookup itself over each texel: a midpoint
// rule on an 8 × 8 grid whose cells do not straddle the texel's quarters, where the lookup
// is bilinear, integrates it exactly (up to float rounding of the lookups).
TEST(EnvironmentLookup, TexelMeanIsTheMeanOfTheFilteredLookup) {
  constexpr int kWidth = 5, kHeight = 4;
  std::vector<float> texels, values;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const float v = static_cast<float>((7 * i + 3) % 11) + (i == 13 ? 30.0f : 0.0f);
    texels.insert(texels.end(), 3, v);
    values.push_back(v);
  }
  const TextureImage map = rgb_map(kWidth, kHeight, texels);
  for (EnvironmentMapping mapping : {EnvironmentMapping::equirectangular, EnvironmentMapping::equal_area_octahedral})
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        double integral = 0.0;
        for (int j = 0; j < 8; ++j)
          for (int i = 0; i < 8; ++i) {
            const Vec2f uv((x + (i + 0.5f) / 8.0f) / kWidth, (y + (j + 0.5f) / 8.0f) / kHeight);
            integral += environment_radiance_bilinear(map, mapping, uv).y / 64.0;
          }
        EXPECT_NEAR(environment_texel_mean(values, mapping, x, y, kWidth, kHeight), integral, 1e-5 * 40.0)
            << static_cast<int>(mapping) << " texel " << x << " " << y;
      }
}

}  // namespace
}  // namespace prism
