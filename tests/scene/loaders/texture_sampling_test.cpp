#include <gtest/gtest.h>

#include "prism/scene/texture_sampling.h"

namespace prism {
namespace {

// A 2×2 single-channel texture: 0 1 / 2 3 (row 0 on top).
TextureImage tiny(TextureWrap wrap) {
  TextureImage t;
  t.width = t.height = 2;
  t.channels = 1;
  t.texels = {0, 1, 2, 3};
  t.wrap_u = t.wrap_v = wrap;
  return t;
}

TEST(TextureSampling, WrapModesMapTexelCoordinates) {
  EXPECT_EQ(wrap_texel_coordinate(-1, 4, TextureWrap::repeat), 3);
  EXPECT_EQ(wrap_texel_coordinate(9, 4, TextureWrap::repeat), 1);
  EXPECT_EQ(wrap_texel_coordinate(-1, 4, TextureWrap::clamp), 0);
  EXPECT_EQ(wrap_texel_coordinate(7, 4, TextureWrap::clamp), 3);
  // Mirror: 0 1 2 3 | 3 2 1 0 | 0 1 ...
  EXPECT_EQ(wrap_texel_coordinate(4, 4, TextureWrap::mirror), 3);
  EXPECT_EQ(wrap_texel_coordinate(7, 4, TextureWrap::mirror), 0);
  EXPECT_EQ(wrap_texel_coordinate(8, 4, TextureWrap::mirror), 0);
  EXPECT_EQ(wrap_texel_coordinate(-1, 4, TextureWrap::mirror), 0);
  EXPECT_EQ(wrap_texel_coordinate(-5, 4, TextureWrap::mirror), 3);
}

TEST(TextureSampling, BilinearExactValues) {
  const TextureImage t = tiny(TextureWrap::clamp);
  // Texel centres return the texel; the image centre averages all four; edges interpolate.
  EXPECT_FLOAT_EQ(sample_bilinear(t, {0.25f, 0.25f})[0], 0.0f);
  EXPECT_FLOAT_EQ(sample_bilinear(t, {0.75f, 0.75f})[0], 3.0f);
  EXPECT_FLOAT_EQ(sample_bilinear(t, {0.5f, 0.5f})[0], 1.5f);
  EXPECT_FLOAT_EQ(sample_bilinear(t, {0.5f, 0.25f})[0], 0.5f);
  EXPECT_FLOAT_EQ(sample_bilinear(t, {0.0f, 0.0f})[0], 0.0f);  // clamp: the corner texel
  const TexelRgba grey = sample_bilinear(t, {0.75f, 0.25f});
  EXPECT_EQ(grey, (TexelRgba{1.0f, 1.0f, 1.0f, 1.0f}));  // grey expands, alpha 1
}

TEST(TextureSampling, BilinearWrapModesAtTheEdge) {
  // At u = 0 (between texel column -1 and 0) on the top row's centre line:
  // repeat mixes column 1 and 0 → 0.5; mirror mixes column 0 with itself → 0; clamp → 0.
  EXPECT_FLOAT_EQ(sample_bilinear(tiny(TextureWrap::repeat), {0.0f, 0.25f})[0], 0.5f);
  EXPECT_FLOAT_EQ(sample_bilinear(tiny(TextureWrap::mirror), {0.0f, 0.25f})[0], 0.0f);
  EXPECT_FLOAT_EQ(sample_bilinear(tiny(TextureWrap::clamp), {0.0f, 0.25f})[0], 0.0f);
  // Repeat is periodic, also far away and for negative uvs.
  EXPECT_FLOAT_EQ(sample_bilinear(tiny(TextureWrap::repeat), {-41.5f, 1000.5f})[0], 1.5f);
  // Absurd uvs neither crash nor return NaN.
  EXPECT_TRUE(std::isfinite(sample_bilinear(tiny(TextureWrap::repeat), {1e30f, -1e30f})[0]));
  EXPECT_TRUE(std::isfinite(sample_bilinear(tiny(TextureWrap::mirror), {NAN, INFINITY})[0]));
}

TEST(TextureSampling, MipPyramidIsABoxFilter) {
  TextureImage t;
  t.width = 4;
  t.height = 2;
  t.channels = 2;
  for (int i = 0; i < 8; ++i) t.texels.insert(t.texels.end(), {static_cast<float>(i), 1.0f});
  const MipPyramid p = build_mip_pyramid(t);
  ASSERT_EQ(p.levels.size(), 3u);  // 4×2, 2×1, 1×1
  EXPECT_EQ(p.levels[1].width, 2);
  EXPECT_EQ(p.levels[1].height, 1);
  // Level 1 texel 0 averages texels 0, 1, 4, 5; texel 1 averages 2, 3, 6, 7.
  EXPECT_FLOAT_EQ(p.levels[1].texels[0], 2.5f);
  EXPECT_FLOAT_EQ(p.levels[1].texels[2], 4.5f);
  EXPECT_FLOAT_EQ(p.levels[2].texels[0], 3.5f);
  EXPECT_FLOAT_EQ(p.levels[2].texels[1], 1.0f);  // alpha stays 1
}

TEST(TextureSampling, OddSizesKeepEveryTexel) {
  TextureImage t;
  t.width = 3;
  t.height = 1;
  t.channels = 1;
  t.texels = {3, 6, 9};
  const MipPyramid p = build_mip_pyramid(t);
  ASSERT_EQ(p.levels.size(), 2u);
  EXPECT_FLOAT_EQ(p.levels[1].texels[0], 6.0f);
}

TEST(TextureSampling, LevelOfDetailFromAKnownFootprint) {
  TextureImage t;
  t.width = t.height = 64;
  t.channels = 1;
  t.texels.assign(64 * 64, 0.5f);
  const MipPyramid p = build_mip_pyramid(t);
  ASSERT_EQ(p.levels.size(), 7u);
  // A pixel spanning 4 texels along u and 1 along v: λ = log2 4 = 2.
  EXPECT_FLOAT_EQ(mip_level_from_uv_derivatives(p, {4.0f / 64, 0.0f}, {0.0f, 1.0f / 64}), 2.0f);
  EXPECT_FLOAT_EQ(mip_level_from_uv_derivatives(p, {0.5f / 64, 0.0f}, {0.0f, 0.5f / 64}), -1.0f);
  // Ray cone: a unit-uv square of 2 × 2 world units (uv area 1/2, world area 2 per
  // triangle) seen head-on by a cone 0.25 units wide covers 0.25 · 64/2 = 8 texels: λ = 3;
  // at 60° incidence the footprint doubles: λ = 4.
  EXPECT_NEAR(mip_level_from_ray_cone(p, 0.25f, 1.0f, 0.5f, 2.0f), 3.0f, 1e-6f);
  EXPECT_NEAR(mip_level_from_ray_cone(p, 0.25f, 0.5f, 0.5f, 2.0f), 4.0f, 1e-6f);
}

TEST(TextureSampling, TrilinearBlendsNeighbouringLevels) {
  // 2×2 checker of 0 and 1: level 0 at a texel centre is 0 or 1, level 1 is 0.5.
  TextureImage t;
  t.width = t.height = 2;
  t.channels = 1;
  t.texels = {0, 1, 1, 0};
  const MipPyramid p = build_mip_pyramid(t);
  const Vec2f centre_of_texel_0{0.25f, 0.25f};
  EXPECT_FLOAT_EQ(sample_trilinear(p, centre_of_texel_0, 0.0f)[0], 0.0f);
  EXPECT_FLOAT_EQ(sample_trilinear(p, centre_of_texel_0, 1.0f)[0], 0.5f);
  EXPECT_FLOAT_EQ(sample_trilinear(p, centre_of_texel_0, 0.5f)[0], 0.25f);
  EXPECT_FLOAT_EQ(sample_trilinear(p, centre_of_texel_0, 9.0f)[0], 0.5f);   // clamped to the coarsest
  EXPECT_FLOAT_EQ(sample_trilinear(p, centre_of_texel_0, -3.0f)[0], 0.0f);  // and the finest
}

}  // namespace
}  // namespace prism
