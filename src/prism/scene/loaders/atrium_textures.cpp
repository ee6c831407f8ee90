#include "prism/scene/loaders/atrium_textures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace prism::loaders {
namespace {

// An integer hash with good avalanche (the "lowbias32" constants from Chris Wellons'
// hash-prospector search); the textures only need it to look random and be repeatable.
std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// A number in [0, 1) from a few integers.
float hash01(std::uint32_t a, std::uint32_t b, std::uint32_t seed) {
  return static_cast<float>(hash32(a ^ hash32(b ^ hash32(seed))) >> 8) * (1.0f / 16777216.0f);
}

// Value noise: hashed lattice values every `cell` texels, interpolated with a smoothstep,
// periodic over `period` texels (a multiple of `cell`) so the texture tiles seamlessly.
float value_noise(int x, int y, int cell, int period, std::uint32_t seed) {
  const int cells = period / cell;
  const int cx = x / cell, cy = y / cell;
  const float fx = static_cast<float>(x % cell) / static_cast<float>(cell);
  const float fy = static_cast<float>(y % cell) / static_cast<float>(cell);
  const auto lattice = [&](int i, int j) {
    return hash01(static_cast<std::uint32_t>(i % cells), static_cast<std::uint32_t>(j % cells), seed);
  };
  const float sx = fx * fx * (3.0f - 2.0f * fx), sy = fy * fy * (3.0f - 2.0f * fy);
  const float top = lattice(cx, cy) + sx * (lattice(cx + 1, cy) - lattice(cx, cy));
  const float bottom = lattice(cx, cy + 1) + sx * (lattice(cx + 1, cy + 1) - lattice(cx, cy + 1));
  return top + sy * (bottom - top);
}

// 8-bit codes, interleaved, row 0 at the top.
struct CodeImage {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> codes;

  CodeImage(int w, int h, int c) : width(w), height(h), channels(c), codes(static_cast<std::size_t>(w) * h * c) {}
  std::uint8_t* at(int x, int y) { return &codes[(static_cast<std::size_t>(y) * width + x) * channels]; }
};

// An sRGB colour (codes 0–255 as floats) scaled by `factor`, rounded to codes.
void put_rgb(std::uint8_t* texel, const std::array<float, 3>& srgb, float factor) {
  for (int c = 0; c < 3; ++c) texel[c] = static_cast<std::uint8_t>(std::clamp(std::lround(srgb[c] * factor), 0L, 255L));
}

// The codes as an 8-bit sRGB texture, as texture_file.cpp keeps an 8-bit PNG: colour
// channels decoded through the IEC 61966-2-1 EOTF, alpha (the 4th of RGBA) linearly.
TextureImage srgb_texture(CodeImage image, std::string name) {
  TextureImage t;
  t.name = std::move(name);
  t.width = image.width;
  t.height = image.height;
  t.channels = image.channels;
  t.codes = std::move(image.codes);
  t.encoding = TextureEncoding::srgb;
  return t;
}

}  // namespace

TextureImage make_floor_tile_texture() {
  constexpr int kSize = 512, kTile = 128, kGrout = 2;  // grout: 2 px either side of a joint
  constexpr std::array<float, 3> kCream{214, 202, 178}, kTerracotta{158, 78, 52}, kGroutColor{118, 112, 102};
  CodeImage image(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int tx = x / kTile, ty = y / kTile, lx = x % kTile, ly = y % kTile;
      const float grain = 0.94f + 0.12f * hash01(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 1u);
      const bool grout = lx < kGrout || ly < kGrout || lx >= kTile - kGrout || ly >= kTile - kGrout;
      if (grout) {
        put_rgb(image.at(x, y), kGroutColor, grain);
        continue;
      }
      const float tint = 0.88f + 0.22f * hash01(static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty), 2u);
      const float mottle = 0.92f + 0.16f * value_noise(x, y, 16, kSize, 3u);
      put_rgb(image.at(x, y), (tx + ty) % 2 == 0 ? kCream : kTerracotta, tint * mottle * (0.5f + 0.5f * grain));
    }
  return srgb_texture(std::move(image), "floor-tiles");
}

TextureImage make_wall_block_texture() {
  constexpr int kSize = 512, kBlockW = 128, kBlockH = 64, kMortar = 3;
  constexpr std::array<float, 3> kSandstone{200, 174, 134}, kMortarColor{176, 168, 152};
  CodeImage image(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int row = y / kBlockH;
      const int shifted = (x + (row % 2) * (kBlockW / 2)) % kSize;  // running bond
      const int column = shifted / kBlockW, lx = shifted % kBlockW, ly = y % kBlockH;
      const float grain = 0.95f + 0.1f * hash01(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 4u);
      if (lx < kMortar || ly < kMortar) {
        put_rgb(image.at(x, y), kMortarColor, grain);
        continue;
      }
      const float tint = 0.84f + 0.26f * hash01(static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row), 5u);
      const float weathering = 0.85f + 0.25f * value_noise(x, y, 32, kSize, 6u);
      put_rgb(image.at(x, y), kSandstone, tint * weathering * grain);
    }
  return srgb_texture(std::move(image), "wall-blocks");
}

TextureImage make_leaf_texture() {
  constexpr int kSize = 256, kLeaves = 14;
  constexpr float kPi = std::numbers::pi_v<float>;
  constexpr std::array<float, 3> kBackground{46, 74, 34}, kStem{88, 96, 40};
  CodeImage image(kSize, kSize, 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      put_rgb(image.at(x, y), kBackground, 1.0f);  // RGB under alpha 0 stays leaf-like for filtering
      image.at(x, y)[3] = 0;
    }
  // The stem: from the foot (bottom centre) up to 12 px below the top, 3 px wide.
  const float stem_x = 0.5f * kSize, stem_top = 12.0f, stem_foot = kSize - 4.0f;
  for (int y = static_cast<int>(stem_top); y < static_cast<int>(stem_foot); ++y)
    for (int x = static_cast<int>(stem_x) - 1; x <= static_cast<int>(stem_x) + 1; ++x) {
      put_rgb(image.at(x, y), kStem, 1.0f);
      image.at(x, y)[3] = 255;
    }
  // Leaves alternate left and right up the stem, each a pointed blade: a point at distance
  // `along` from the blade's centre line midpoint is inside when |across| ≤ w (1 − t²),
  // t = along / half-length.
  for (int i = 0; i < kLeaves; ++i) {
    const float h = hash01(static_cast<std::uint32_t>(i), 7u, 8u), g = hash01(static_cast<std::uint32_t>(i), 9u, 10u);
    const float side = i % 2 == 0 ? -1.0f : 1.0f;
    const float attach_y = stem_foot - 20.0f - (stem_foot - stem_top - 40.0f) * static_cast<float>(i) / (kLeaves - 1);
    const float half_length = 30.0f + 14.0f * h - 10.0f * static_cast<float>(i) / kLeaves;
    const float half_width = 0.32f * half_length;
    const float angle = side * (0.35f + 0.5f * g) * kPi * 0.5f;  // from vertical, outwards
    const float dx = std::sin(angle), dy = -std::cos(angle);      // up the image is −y
    const float cx = stem_x + dx * half_length, cy = attach_y + dy * half_length;
    const std::array<float, 3> green{60.0f + 40.0f * h, 110.0f + 50.0f * g, 40.0f + 20.0f * h};
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const float px = static_cast<float>(x) + 0.5f - cx, py = static_cast<float>(y) + 0.5f - cy;
        const float along = px * dx + py * dy, across = px * dy - py * dx;
        const float t = along / half_length;
        if (std::abs(t) > 1.0f || std::abs(across) > half_width * (1.0f - t * t)) continue;
        if (x < 1 || y < 1 || x >= kSize - 1 || y >= kSize - 1) continue;  // keep the border clear
        const float midrib = std::abs(across) < 1.0f ? 1.25f : 1.0f;
        const float shade = 0.85f + 0.3f * hash01(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 11u);
        put_rgb(image.at(x, y), green, midrib * (0.8f + 0.2f * shade) * (1.0f - 0.25f * std::abs(across) / half_width));
        image.at(x, y)[3] = 255;
      }
  }
  return srgb_texture(std::move(image), "leaves");
}

}  // namespace prism::loaders
