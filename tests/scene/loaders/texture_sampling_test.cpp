#include <gtest/gtest.h>

#include "prism/core/half_float.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "prism/color/transfer_functions.h"
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

// Bilinear filtering by its definition: the four texels around the continuous coordinate,
// each wrapped on its own by wrap_texel_coordinate (std::floor, integer remainders).
TexelRgba bilinear_by_definition(const MipLevel& level, int channels, Vec2f uv, TextureWrap wrap_u,
                                 TextureWrap wrap_v) {
  const double x = static_cast<double>(uv.x) * level.width - 0.5, y = static_cast<double>(uv.y) * level.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  const TexelRgba a = texel_fetch(level, channels, ix, iy, wrap_u, wrap_v);
  const TexelRgba b = texel_fetch(level, channels, ix + 1, iy, wrap_u, wrap_v);
  const TexelRgba c = texel_fetch(level, channels, ix, iy + 1, wrap_u, wrap_v);
  const TexelRgba d = texel_fetch(level, channels, ix + 1, iy + 1, wrap_u, wrap_v);
  TexelRgba r;
  for (int k = 0; k < 4; ++k) r[k] = (1 - fy) * ((1 - fx) * a[k] + fx * b[k]) + fy * ((1 - fx) * c[k] + fx * d[k]);
  return r;
}

// sample_bilinear wraps each column and row once and reduces coordinates without divisions
// where it can; it must pick the same texels with the same weights as the definition, bit
// for bit, for every wrap mode, odd and one-texel sizes, any channel count, and uvs far
// outside [0, 1] on either side (texel coordinates up to ±4e5, which the definition's int
// conversion still holds).
TEST(TextureSampling, BilinearMatchesItsDefinitionBitForBit) {
  const TextureWrap modes[] = {TextureWrap::repeat, TextureWrap::clamp, TextureWrap::mirror};
  const int sizes[][2] = {{1, 1}, {2, 3}, {5, 4}, {7, 1}, {16, 9}};
  std::uint32_t state = 12345u;
  const auto next_unit = [&] {  // xorshift32: reproducible uvs without the samplers under test
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return static_cast<float>(state >> 8) * 0x1p-24f;
  };
  int compared = 0;
  for (const auto& size : sizes)
    for (int channels = 1; channels <= 4; ++channels) {
      MipLevel level;
      level.width = size[0];
      level.height = size[1];
      for (int i = 0; i < size[0] * size[1] * channels; ++i)
        level.texels.push_back(static_cast<float>(i * 7 % 13) + 0.25f);
      for (TextureWrap wrap_u : modes)
        for (TextureWrap wrap_v : modes)
          for (int n = 0; n < 400; ++n) {
            // Spans of 2, 20 and 2e4 around 0: near the image, a few periods off, far off.
            const float span = n % 3 == 0 ? 2.0f : (n % 3 == 1 ? 20.0f : 2e4f);
            Vec2f uv{(next_unit() - 0.5f) * span, (next_unit() - 0.5f) * span};
            if (n % 7 == 0) uv.x = std::round(uv.x * size[0]) / size[0];  // exactly on texel edges, too
            if (n % 11 == 0) uv.y = (std::round(uv.y * size[1] - 0.5f) + 0.5f) / size[1];  // and on centres
            const TexelRgba expected = bilinear_by_definition(level, channels, uv, wrap_u, wrap_v);
            const TexelRgba got = sample_bilinear(level, channels, uv, wrap_u, wrap_v);
            ASSERT_EQ(got, expected) << "size " << size[0] << "x" << size[1] << ", " << channels << " channels, wrap "
                                     << int(wrap_u) << "/" << int(wrap_v) << ", uv (" << uv.x << ", " << uv.y << ")";
            ++compared;
          }
    }
  EXPECT_EQ(compared, 5 * 4 * 9 * 400);
}

// A texture transform without rotation takes a shortcut (no cos/sin); both must agree.
TEST(TextureSampling, UvTransformWithoutRotationIsScaleAndOffset) {
  TextureImage t;
  t.offset_u = 0.25f;
  t.offset_v = -1.5f;
  t.scale_u = 3.0f;
  t.scale_v = 0.5f;
  const Vec2f uv = apply_uv_transform(t, {0.2f, 0.7f});
  EXPECT_FLOAT_EQ(uv.x, 0.25f + 3.0f * 0.2f);
  EXPECT_FLOAT_EQ(uv.y, -1.5f + 0.5f * 0.7f);
  // A quarter turn (KHR_texture_transform rotates uv by −rotation): (u, v) ↦ (v, −u), then scale and offset.
  t.rotation_radians = std::numbers::pi_v<float> / 2;
  const Vec2f turned = apply_uv_transform(t, {0.2f, 0.7f});
  EXPECT_NEAR(turned.x, 0.25f + 3.0f * 0.7f, 1e-6f);
  EXPECT_NEAR(turned.y, -1.5f + 0.5f * -0.2f, 1e-6f);
}

TEST(TextureSampling, MipPyramidIsABoxFilter) {
  TextureImage t;
  t.width = 4;
  t.height = 2;
  t.channels = 2;
  for (int i = 0; i < 8; ++i) t.texels.insert(t.texels.end(), {static_cast<float>(i), 1.0f});
  const MipPyramid p = build_mip_pyramid(t);
  ASSERT_EQ(p.levels.size(), 3u);  // 4×2, 2×1, 1×1
  // Level 0 is the texture's own texels, not a copy of them.
  EXPECT_EQ(p.levels[0].data(), t.texels.data());
  EXPECT_TRUE(p.levels[0].texels.empty());
  EXPECT_EQ(texel_fetch(p.levels[0], 2, 3, 1, TextureWrap::clamp, TextureWrap::clamp)[0], 7.0f);
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

// Every level is the box filter summed as its definition reads: each coarse texel's fine
// texels in row-major order from 0, then × ¼ for four of them (the same real number as ÷ 4)
// or ÷ n on the last row and column of an odd size. Compared bit for bit, so a filter
// that sums in another order (which rounds differently) fails, and images that depend on
// the levels stay as they were.
TEST(TextureSampling, MipLevelsAreTheBoxFilterSummedInRowMajorOrder) {
  for (int channels = 1; channels <= 4; ++channels) {
    TextureImage t;
    t.width = 37;
    t.height = 22;
    t.channels = channels;
    std::uint32_t state = 12345u + static_cast<std::uint32_t>(channels);
    for (int i = 0; i < t.width * t.height * channels; ++i) {
      state = state * 1664525u + 1013904223u;  // LCG: arbitrary values with full mantissas
      t.texels.push_back(static_cast<float>(state >> 8) * 0x1p-24f * 3.0f);
    }
    const MipPyramid p = build_mip_pyramid(t);
    std::vector<float> fine = t.texels;
    int fine_width = t.width, fine_height = t.height;
    for (std::size_t l = 1; l < p.levels.size(); ++l) {
      const int width = std::max(1, fine_width / 2), height = std::max(1, fine_height / 2);
      ASSERT_EQ(p.levels[l].width, width);
      ASSERT_EQ(p.levels[l].height, height);
      std::vector<float> coarse;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          const int y_end = y == height - 1 ? fine_height : 2 * y + 2, x_end = x == width - 1 ? fine_width : 2 * x + 2;
          for (int k = 0; k < channels; ++k) {
            float sum = 0.0f;
            for (int fy = std::min(2 * y, fine_height - 1); fy < std::min(y_end, fine_height); ++fy)
              for (int fx = std::min(2 * x, fine_width - 1); fx < std::min(x_end, fine_width); ++fx)
                sum += fine[(static_cast<std::size_t>(fy) * fine_width + fx) * channels + k];
            const int n = (std::min(y_end, fine_height) - std::min(2 * y, fine_height - 1)) *
                          (std::min(x_end, fine_width) - std::min(2 * x, fine_width - 1));
            coarse.push_back(n == 4 ? sum * 0.25f : sum / static_cast<float>(n));
          }
        }
      ASSERT_EQ(p.levels[l].texels.size(), coarse.size());
      for (std::size_t i = 0; i < coarse.size(); ++i)
        ASSERT_EQ(p.levels[l].texels[i], coarse[i]) << "channels " << channels << " level " << l << " value " << i;
      fine = std::move(coarse);
      fine_width = width;
      fine_height = height;
    }
  }
  TextureImage five;
  five.width = five.height = 2;
  five.channels = 5;
  five.texels.assign(20, 0.5f);
  EXPECT_THROW(build_mip_pyramid(five), std::invalid_argument);  // texels are 1 to 4 channels
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

// An 8-bit image of `channels` channels with a pseudo-random pattern of codes, and the
// same image as the floats its codes decode to.
TextureImage coded_image(int width, int height, int channels, TextureEncoding encoding, std::uint32_t seed) {
  TextureImage t;
  t.width = width;
  t.height = height;
  t.channels = channels;
  t.encoding = encoding;
  std::uint32_t state = seed;
  for (int i = 0; i < width * height * channels; ++i) {
    state = state * 1664525u + 1013904223u;
    t.codes.push_back(static_cast<std::uint8_t>(state >> 24));
  }
  return t;
}

TextureImage as_floats(const TextureImage& coded) {
  TextureImage t = coded;
  t.texels = coded.linear_values();
  t.codes.clear();
  return t;
}

// The floats an RGBE image decodes to, by stb_image's formula: mantissa · 2^(e − 136),
// black for e = 0.
TextureImage as_floats_of_rgbe(const TextureImage& rgbe) {
  TextureImage t = rgbe;
  t.rgbe.clear();
  for (std::size_t i = 0; i < rgbe.rgbe.size(); i += 4)
    for (std::size_t k = 0; k < 3; ++k)
      t.texels.push_back(rgbe.rgbe[i + 3] == 0 ? 0.0f
                                               : rgbe.rgbe[i + k] * static_cast<float>(std::ldexp(1.0f, rgbe.rgbe[i + 3] - 136)));
  return t;
}

// Lookups in an image kept as 8-bit codes give bitwise what the floats they decode to give
// (the decode tables are the load-time decoder's), colour channels through the sRGB EOTF
// and alpha linearly.
TEST(TextureSampling, EightBitImagesSampleAsTheirDecodedFloats) {
  for (const TextureEncoding encoding : {TextureEncoding::srgb, TextureEncoding::linear})
    for (int channels = 1; channels <= 4; ++channels) {
      const TextureImage coded = coded_image(7, 5, channels, encoding, 17u + static_cast<std::uint32_t>(channels));
      const TextureImage floats = as_floats(coded);
      for (int i = 0; i < 7 * 5 * channels; ++i) {
        const bool alpha = (channels == 2 || channels == 4) && i % channels == channels - 1;
        const double v = coded.codes[static_cast<std::size_t>(i)] / 255.0;
        const double expected = (alpha || encoding == TextureEncoding::linear) ? v : color::srgb_decode(v);
        ASSERT_EQ(coded.value(static_cast<std::size_t>(i)), static_cast<float>(expected)) << i;
      }
      for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) ASSERT_EQ(texel_rgb(coded, x, y), texel_rgb(floats, x, y)) << x << " " << y;
      const MipPyramid coded_pyramid = build_mip_pyramid(coded), float_pyramid = build_mip_pyramid(floats);
      for (int n = 0; n < 200; ++n) {
        const Vec2f uv{static_cast<float>(n % 23) / 9.0f - 0.7f, static_cast<float>(n % 19) / 7.0f - 0.4f};
        ASSERT_EQ(sample_bilinear(coded, uv), sample_bilinear(floats, uv)) << n;
        ASSERT_EQ(sample_trilinear(coded_pyramid, uv, 0.0f), sample_trilinear(float_pyramid, uv, 0.0f)) << n;
        ASSERT_EQ(texel_fetch(coded_pyramid.levels[0], channels, n % 9 - 1, n % 6, TextureWrap::repeat,
                              TextureWrap::mirror),
                  texel_fetch(float_pyramid.levels[0], channels, n % 9 - 1, n % 6, TextureWrap::repeat,
                              TextureWrap::mirror))
            << n;
      }
    }
}

// Every lookup in `stored` (texels kept in a compact form) equals the lookup in `floats`
// (the same image as the floats that form decodes to): texel_rgb, the coarser mip levels,
// bilinear, trilinear and texel_fetch at wrapped and mirrored coordinates.
void expect_lookups_as_floats(const TextureImage& stored, const TextureImage& floats) {
  for (int y = 0; y < stored.height; ++y)
    for (int x = 0; x < stored.width; ++x) ASSERT_EQ(texel_rgb(stored, x, y), texel_rgb(floats, x, y)) << x << " " << y;
  const MipPyramid stored_pyramid = build_mip_pyramid(stored), float_pyramid = build_mip_pyramid(floats);
  ASSERT_EQ(stored_pyramid.levels.size(), float_pyramid.levels.size());
  for (std::size_t l = 1; l < stored_pyramid.levels.size(); ++l)
    EXPECT_EQ(stored_pyramid.levels[l].texels, float_pyramid.levels[l].texels) << l;
  const int c = stored.channels;
  for (int n = 0; n < 200; ++n) {
    const Vec2f uv{static_cast<float>(n % 23) / 9.0f - 0.7f, static_cast<float>(n % 19) / 7.0f - 0.4f};
    const float lod = static_cast<float>(n % 7) * 0.4f;
    ASSERT_EQ(sample_bilinear(stored, uv), sample_bilinear(floats, uv)) << n;
    ASSERT_EQ(sample_trilinear(stored_pyramid, uv, lod), sample_trilinear(float_pyramid, uv, lod)) << n;
    ASSERT_EQ(texel_fetch(stored_pyramid.levels[0], c, n % 11 - 1, n % 7, TextureWrap::repeat, TextureWrap::mirror),
              texel_fetch(float_pyramid.levels[0], c, n % 11 - 1, n % 7, TextureWrap::repeat, TextureWrap::mirror))
        << n;
  }
}

// A Radiance image kept as RGBE samples as the floats it decodes to, bitwise: at level 0
// (borrowed, 4 bytes per texel) and through its float levels below.
TEST(TextureSampling, RgbeImagesSampleAsTheirDecodedFloats) {
  TextureImage rgbe;
  rgbe.width = 9;
  rgbe.height = 6;
  rgbe.channels = 3;
  std::uint32_t state = 3;
  for (int t = 0; t < 9 * 6; ++t) {
    for (int k = 0; k < 4; ++k) {
      state = state * 1664525u + 1013904223u;
      rgbe.rgbe.push_back(static_cast<std::uint8_t>(k < 3 ? state >> 24 : 120 + (state >> 28)));
    }
  }
  rgbe.rgbe[3] = 0;  // a black texel: exponent 0
  const TextureImage floats = as_floats_of_rgbe(rgbe);
  ASSERT_EQ(floats.texels.size(), 9u * 6u * 3u);
  EXPECT_EQ(floats.texels[0], 0.0f);
  EXPECT_EQ(rgbe.memory_bytes(), 9u * 6u * 4u);
  EXPECT_EQ(build_mip_pyramid(rgbe).levels[0].borrowed_rgbe, rgbe.rgbe.data());  // borrowed, not copied
  expect_lookups_as_floats(rgbe, floats);
}

// A half-float image (OpenEXR HALF channels) samples bitwise as the floats its halves are
// (half_bits_to_float, checked against Imath in half_float_test), with 1 to 4 channels:
// level 0 borrowed as halves, its coarser levels the float image's levels, and every
// lookup equal, subnormal, negative and large halves included.
TEST(TextureSampling, HalfFloatImagesSampleAsTheirFloats) {
  for (int channels = 1; channels <= 4; ++channels) {
    TextureImage halves;
    halves.width = 9;
    halves.height = 6;
    halves.channels = channels;
    std::uint32_t state = 11u + static_cast<std::uint32_t>(channels);
    for (int i = 0; i < 9 * 6 * channels; ++i) {
      state = state * 1664525u + 1013904223u;
      halves.halves.push_back(static_cast<std::uint16_t>(state >> 17));  // every exponent, both signs
    }
    halves.halves[0] = 0x0001;  // the smallest subnormal
    halves.halves[1] = 0x7bff;  // the largest finite half
    TextureImage floats = halves;
    floats.halves.clear();
    for (const std::uint16_t h : halves.halves) floats.texels.push_back(half_bits_to_float(h));
    // NaN and infinite samples would make the equality checks below vacuous: keep finite ones.
    for (std::size_t i = 0; i < floats.texels.size(); ++i)
      if (!std::isfinite(floats.texels[i])) halves.halves[i] = 0x3c00, floats.texels[i] = 1.0f;
    EXPECT_EQ(halves.memory_bytes(), 9u * 6u * 2u * static_cast<std::size_t>(channels));
    EXPECT_EQ(halves.linear_values(), floats.texels);
    EXPECT_EQ(build_mip_pyramid(halves).levels[0].borrowed_halves, halves.halves.data());  // borrowed, not copied
    expect_lookups_as_floats(halves, floats);
  }
}

// The levels of an 8-bit image are 8-bit, level 0 borrowed from the image; every texel of
// a coarser level is the code whose value is nearest to the box filter's exact average,
// i.e. to the float pyramid of the decoded image (whose levels are each averaged from the
// unrounded level above, as the 8-bit pyramid's are).
TEST(TextureSampling, EightBitLevelsHoldTheCodeNearestTheAverage) {
  for (const TextureEncoding encoding : {TextureEncoding::srgb, TextureEncoding::linear})
    for (int channels = 1; channels <= 4; ++channels) {
      const TextureImage coded = coded_image(37, 22, channels, encoding, 5u + static_cast<std::uint32_t>(channels));
      const MipPyramid pyramid = build_mip_pyramid(coded);
      const TextureImage floats = as_floats(coded);
      const MipPyramid exact = build_mip_pyramid(floats);
      ASSERT_EQ(pyramid.levels.size(), exact.levels.size());
      EXPECT_EQ(pyramid.levels[0].code_data(), coded.codes.data());  // borrowed, not copied
      EXPECT_EQ(pyramid.levels[0].owned_bytes(), 0u);
      for (std::size_t l = 1; l < pyramid.levels.size(); ++l) {
        const MipLevel& level = pyramid.levels[l];
        ASSERT_TRUE(level.has_codes());
        ASSERT_EQ(level.codes.size(), exact.levels[l].texels.size());
        EXPECT_EQ(level.owned_bytes(), level.codes.size());  // a byte per sample
        for (std::size_t i = 0; i < level.codes.size(); ++i) {
          const bool alpha = (channels == 2 || channels == 4) && static_cast<int>(i) % channels == channels - 1;
          const std::array<float, 256>& values = code_values(alpha ? TextureEncoding::linear : encoding);
          const float target = exact.levels[l].texels[i];
          const int code = level.codes[i];
          const float error = std::abs(values[static_cast<std::size_t>(code)] - target);
          if (code > 0) {
            ASSERT_LE(error, std::abs(values[static_cast<std::size_t>(code - 1)] - target)) << l << " " << i;
          }
          if (code < 255) {
            ASSERT_LE(error, std::abs(values[static_cast<std::size_t>(code + 1)] - target)) << l << " " << i;
          }
        }
      }
    }
}

}  // namespace
}  // namespace prism
