#include "prism/scene/texture_sampling.h"

#include "prism/scene/nearest_code.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace prism {

int wrap_texel_coordinate(int i, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::clamp:
      return std::clamp(i, 0, size - 1);
    case TextureWrap::mirror: {
      const int period = 2 * size;
      int t = i % period;
      if (t < 0) t += period;
      return t < size ? t : period - 1 - t;
    }
    case TextureWrap::repeat:
      break;
  }
  const int t = i % size;
  return t < 0 ? t + size : t;
}

Vec2f apply_uv_transform(const TextureImage& t, Vec2f uv) {
  // Most textures are not rotated: no cos and sin per lookup then (the products with 1 and
  // ±0 they would give change nothing but the sign of a zero uv, which no texel sees).
  if (t.rotation_radians == 0.0f) return {t.offset_u + t.scale_u * uv.x, t.offset_v + t.scale_v * uv.y};
  const float c = std::cos(t.rotation_radians), s = std::sin(t.rotation_radians);
  // KHR_texture_transform: uv' = offset + scale ⊙ (R · uv) with R rotating by -rotation.
  const float ru = c * uv.x + s * uv.y, rv = -s * uv.x + c * uv.y;
  return {t.offset_u + t.scale_u * ru, t.offset_v + t.scale_v * rv};
}

namespace {

// The texel at wrapped coordinates (xi, yi) ∈ [0, width) × [0, height) of a float level,
// or of an 8-bit one through its value tables. Always inlined, like
// wrap_reduced_coordinate: GCC otherwise calls them out of line from bilinear()'s four
// sites, and the texel comes back through memory.
struct FloatTexels {
  const float* texels;
  int width, channels;
  [[gnu::always_inline]] TexelRgba operator()(int xi, int yi) const {
    const float* p = texels + (static_cast<std::size_t>(yi) * width + xi) * channels;
    switch (channels) {
      case 1: return {p[0], p[0], p[0], 1.0f};
      case 2: return {p[0], p[0], p[0], p[1]};
      case 3: return {p[0], p[1], p[2], 1.0f};
      default: return {p[0], p[1], p[2], p[3]};
    }
  }
};

struct CodedTexels {
  const std::uint8_t* codes;
  int width, channels;
  const float* colour;  // code → value of the colour channels
  const float* alpha;   // code → value of alpha (linear)
  [[gnu::always_inline]] TexelRgba operator()(int xi, int yi) const {
    const std::uint8_t* p = codes + (static_cast<std::size_t>(yi) * width + xi) * channels;
    switch (channels) {
      case 1: return {colour[p[0]], colour[p[0]], colour[p[0]], 1.0f};
      case 2: return {colour[p[0]], colour[p[0]], colour[p[0]], alpha[p[1]]};
      case 3: return {colour[p[0]], colour[p[1]], colour[p[2]], 1.0f};
      default: return {colour[p[0]], colour[p[1]], colour[p[2]], alpha[p[3]]};
    }
  }
};

// RGB texels of a Radiance image: three mantissas and a shared exponent (texture.h).
struct RgbeTexels {
  const std::uint8_t* rgbe;
  int width;
  [[gnu::always_inline]] TexelRgba operator()(int xi, int yi) const {
    const std::uint8_t* p = rgbe + (static_cast<std::size_t>(yi) * width + xi) * 4;
    return {rgbe_value(p[0], p[3]), rgbe_value(p[1], p[3]), rgbe_value(p[2], p[3]), 1.0f};
  }
};

// Half-float texels (OpenEXR HALF channels), decoded exactly at each read.
struct HalfTexels {
  const std::uint16_t* halves;
  int width, channels;
  [[gnu::always_inline]] TexelRgba operator()(int xi, int yi) const {
    const std::uint16_t* p = halves + (static_cast<std::size_t>(yi) * width + xi) * channels;
    switch (channels) {
      case 1: { const float v = half_bits_to_float(p[0]); return {v, v, v, 1.0f}; }
      case 2: { const float v = half_bits_to_float(p[0]); return {v, v, v, half_bits_to_float(p[1])}; }
      case 3: return {half_bits_to_float(p[0]), half_bits_to_float(p[1]), half_bits_to_float(p[2]), 1.0f};
      default:
        return {half_bits_to_float(p[0]), half_bits_to_float(p[1]), half_bits_to_float(p[2]), half_bits_to_float(p[3])};
    }
  }
};

// Calls f with the level's texel reader.
template <class F>
[[gnu::always_inline]] inline TexelRgba with_texels(const MipLevel& level, int channels, F&& f) {
  if (level.has_codes())
    return f(CodedTexels{level.code_data(), level.width, channels, level.colour_values,
                         code_values(TextureEncoding::linear).data()});
  if (level.has_rgbe()) return f(RgbeTexels{level.borrowed_rgbe, level.width});
  if (level.has_halves()) return f(HalfTexels{level.borrowed_halves, level.width, channels});
  return f(FloatTexels{level.data(), level.width, channels});
}

// The same for a texture image's own texels.
template <class F>
[[gnu::always_inline]] inline TexelRgba with_texels(const TextureImage& t, F&& f) {
  if (t.has_codes())
    return f(CodedTexels{t.codes.data(), t.width, t.channels, code_values(t.encoding).data(),
                         code_values(TextureEncoding::linear).data()});
  if (t.has_rgbe()) return f(RgbeTexels{t.rgbe.data(), t.width});
  if (t.has_halves()) return f(HalfTexels{t.halves.data(), t.width, t.channels});
  return f(FloatTexels{t.texels.data(), t.width, t.channels});
}

// std::floor without its libm call (the baseline x86-64 build has no SSE4.1 round
// instruction), exact for every double: a magnitude ≥ 2^52 is an integer already, and
// truncation toward zero is one below the floor for negative non-integers.
double floor_exact(double x) {
  if (!(std::abs(x) < 0x1p52)) return x;  // integers, infinities and NaN as they are
  const double truncated = static_cast<double>(static_cast<std::int64_t>(x));
  return truncated > x ? truncated - 1.0 : truncated;
}

// Integer texel coordinate of a floor()ed continuous one, reduced so that it fits an int.
// Clamp keeps one texel of margin; repeat and mirror are periodic with period 2·size, so
// the result lies in [0, 2·size) (the division is skipped where it would change nothing).
int reduce_coordinate(double i, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::clamp) return static_cast<int>(std::clamp(i, -1.0, static_cast<double>(size)));
  const double period = 2.0 * size;
  if (i >= 0.0 && i < period) return static_cast<int>(i);
  return static_cast<int>(i - period * floor_exact(i / period));
}

// wrap_texel_coordinate for the coordinates bilinear() produces: reduce_coordinate's and
// one more, i.e. [-1, size + 1] (clamp) or [0, 2·size] (repeat, mirror), without the
// integer division of the general case (which stays for anything else, e.g. the result of
// reducing an absurd coordinate in floating point).
[[gnu::always_inline]] inline int wrap_reduced_coordinate(int i, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::clamp) return std::clamp(i, 0, size - 1);
  if (i < 0 || i > 2 * size) return wrap_texel_coordinate(i, size, wrap);
  if (i == 2 * size) return 0;  // both periodic modes start over at 2·size
  if (wrap == TextureWrap::repeat) return i < size ? i : i - size;
  return i < size ? i : 2 * size - 1 - i;  // mirror
}

template <class Texels>
TexelRgba bilinear(const Texels& texel, int width, int height, Vec2f uv, TextureWrap wrap_u, TextureWrap wrap_v) {
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = {0.0f, 0.0f};
  // Texel centres sit at half-integers: shift so that integer coordinates are centres.
  const double x = static_cast<double>(uv.x) * width - 0.5, y = static_cast<double>(uv.y) * height - 0.5;
  const double x0 = floor_exact(x), y0 = floor_exact(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const int ix = reduce_coordinate(x0, width, wrap_u), iy = reduce_coordinate(y0, height, wrap_v);
  // Each column and row wrapped once, not once per texel.
  const int x_lo = wrap_reduced_coordinate(ix, width, wrap_u), x_hi = wrap_reduced_coordinate(ix + 1, width, wrap_u);
  const int y_lo = wrap_reduced_coordinate(iy, height, wrap_v), y_hi = wrap_reduced_coordinate(iy + 1, height, wrap_v);
  const TexelRgba a = texel(x_lo, y_lo);
  const TexelRgba b = texel(x_hi, y_lo);
  const TexelRgba c = texel(x_lo, y_hi);
  const TexelRgba d = texel(x_hi, y_hi);
  TexelRgba r;
  for (int k = 0; k < 4; ++k) r[k] = (1 - fy) * ((1 - fx) * a[k] + fx * b[k]) + fy * ((1 - fx) * c[k] + fx * d[k]);
  return r;
}

}  // namespace

TexelRgba texel_fetch(const MipLevel& level, int channels, int x, int y, TextureWrap wrap_u, TextureWrap wrap_v) {
  const int xi = wrap_texel_coordinate(x, level.width, wrap_u), yi = wrap_texel_coordinate(y, level.height, wrap_v);
  return with_texels(level, channels, [&](const auto& texel) { return texel(xi, yi); });
}

TexelRgba sample_bilinear(const MipLevel& level, int channels, Vec2f uv, TextureWrap wrap_u, TextureWrap wrap_v) {
  return with_texels(level, channels, [&](const auto& texel) {
    return bilinear(texel, level.width, level.height, uv, wrap_u, wrap_v);
  });
}

TexelRgba sample_bilinear(const TextureImage& texture, Vec2f uv) {
  const Vec2f st = apply_uv_transform(texture, uv);
  return with_texels(texture, [&](const auto& texel) {
    return bilinear(texel, texture.width, texture.height, st, texture.wrap_u, texture.wrap_v);
  });
}

namespace {

// One box-filtered level below a fine one of fine_width × fine_height texels whose texel t
// has the linear value fine(t, k) in channel k: linear values, C channels per texel. C is a
// template parameter so that the sums stay in registers: summed in the output through
// memory, every addition waited on the store of the one before (the compiler cannot tell
// the output from what `fine` reads).
template <int C, class FineValue>
std::vector<float> box_filter_level(const FineValue& fine, int fine_width, int fine_height, int coarse_width,
                                    int coarse_height) {
  std::vector<float> coarse(static_cast<std::size_t>(coarse_width) * coarse_height * C);
  for (int y = 0; y < coarse_height; ++y) {
    // Fine rows covered by coarse row y: 2y, 2y+1, and 2y+2 for the last row of an odd size.
    const int y_begin = std::min(2 * y, fine_height - 1);
    const int y_end = (y == coarse_height - 1) ? fine_height : std::min(2 * y + 2, fine_height);
    // All but the last row and column: the 2 × 2 texels from (2x, 2y), summed in the order
    // of the general loop below (the same sums), with the loop bounds known.
    const int interior_columns = y < coarse_height - 1 ? coarse_width - 1 : 0;
    for (int x = 0; x < interior_columns; ++x) {
      const std::size_t top = static_cast<std::size_t>(2 * y) * fine_width + 2 * static_cast<std::size_t>(x);
      const std::size_t bottom = top + static_cast<std::size_t>(fine_width);
      std::array<float, C> sum{};
      for (const std::size_t t : {top, top + 1, bottom, bottom + 1})
        for (int k = 0; k < C; ++k) sum[static_cast<std::size_t>(k)] += fine(t, k);
      float* out = coarse.data() + (static_cast<std::size_t>(y) * coarse_width + x) * C;
      for (int k = 0; k < C; ++k) out[k] = sum[static_cast<std::size_t>(k)] * 0.25f;
    }
    for (int x = interior_columns; x < coarse_width; ++x) {
      const int x_begin = std::min(2 * x, fine_width - 1);
      const int x_end = (x == coarse_width - 1) ? fine_width : std::min(2 * x + 2, fine_width);
      std::array<float, C> sum{};  // each channel's sum in the fine texels' row-major order
      for (int fy = y_begin; fy < y_end; ++fy)
        for (int fx = x_begin; fx < x_end; ++fx)
          for (int k = 0; k < C; ++k)
            sum[static_cast<std::size_t>(k)] += fine(static_cast<std::size_t>(fy) * fine_width + fx, k);
      float* out = coarse.data() + (static_cast<std::size_t>(y) * coarse_width + x) * C;
      const int n = (y_end - y_begin) * (x_end - x_begin);
      if (n == 4) {
        // x / 4 and x · 0.25 are the same real number, so they round alike (every texel
        // but the last row and column of an odd size: a multiplication, not a division).
        for (int k = 0; k < C; ++k) out[k] = sum[static_cast<std::size_t>(k)] * 0.25f;
      } else {
        for (int k = 0; k < C; ++k) out[k] = sum[static_cast<std::size_t>(k)] / static_cast<float>(n);
      }
    }
  }
  return coarse;
}

// box_filter_level for the texture's channel count (1 to 4, checked by build_mip_pyramid).
template <class FineValue>
std::vector<float> box_filter_level(const FineValue& fine, int fine_width, int fine_height, int coarse_width,
                                    int coarse_height, int channels) {
  switch (channels) {
    case 1: return box_filter_level<1>(fine, fine_width, fine_height, coarse_width, coarse_height);
    case 2: return box_filter_level<2>(fine, fine_width, fine_height, coarse_width, coarse_height);
    case 3: return box_filter_level<3>(fine, fine_width, fine_height, coarse_width, coarse_height);
    default: return box_filter_level<4>(fine, fine_width, fine_height, coarse_width, coarse_height);
  }
}

// Per encoding, built once (its thresholds take a bisection per code).
const NearestCode& nearest_code(TextureEncoding encoding) {
  static const NearestCode srgb(code_values(TextureEncoding::srgb)), linear(code_values(TextureEncoding::linear));
  return encoding == TextureEncoding::srgb ? srgb : linear;
}

}  // namespace

MipPyramid base_level_pyramid(const TextureImage& texture) {
  MipPyramid pyramid;
  pyramid.channels = texture.channels;
  pyramid.wrap_u = texture.wrap_u;
  pyramid.wrap_v = texture.wrap_v;
  MipLevel base;
  base.width = texture.width;
  base.height = texture.height;
  if (texture.has_codes()) {
    base.borrowed_codes = texture.codes.data();
    base.colour_values = code_values(texture.encoding).data();
  } else if (texture.has_rgbe()) {
    base.borrowed_rgbe = texture.rgbe.data();
  } else if (texture.has_halves()) {
    base.borrowed_halves = texture.halves.data();
  } else {
    base.borrowed = texture.texels.data();
  }
  pyramid.levels.push_back(std::move(base));
  return pyramid;
}

MipPyramid build_mip_pyramid(const TextureImage& texture) {
  // Texels are 1 to 4 channels wherever they are read (TexelRgba); the filter sums as many.
  if (texture.channels < 1 || texture.channels > 4)
    throw std::invalid_argument("build_mip_pyramid: " + std::to_string(texture.channels) + " channels (1 to 4 expected)");
  MipPyramid pyramid = base_level_pyramid(texture);
  const int c = texture.channels;
  if (!texture.has_codes()) {
    while (pyramid.levels.back().width > 1 || pyramid.levels.back().height > 1) {
      const MipLevel& fine = pyramid.levels.back();
      MipLevel coarse;
      coarse.width = std::max(1, fine.width / 2);
      coarse.height = std::max(1, fine.height / 2);
      if (fine.has_rgbe()) {  // level 0 of a Radiance image; float levels below it
        const std::uint8_t* rgbe = fine.borrowed_rgbe;
        coarse.texels = box_filter_level([rgbe](std::size_t t, int k) { return rgbe_value(rgbe[t * 4 + k], rgbe[t * 4 + 3]); },
                                         fine.width, fine.height, coarse.width, coarse.height, c);
      } else if (fine.has_halves()) {  // level 0 of a half-float image; float levels below it
        const std::uint16_t* halves = fine.borrowed_halves;
        coarse.texels =
            box_filter_level([halves, c](std::size_t t, int k) { return half_bits_to_float(halves[t * c + k]); },
                             fine.width, fine.height, coarse.width, coarse.height, c);
      } else {
        const float* values = fine.data();
        coarse.texels = box_filter_level([values, c](std::size_t t, int k) { return values[t * c + k]; }, fine.width,
                                         fine.height, coarse.width, coarse.height, c);
      }
      pyramid.levels.push_back(std::move(coarse));
    }
    return pyramid;
  }
  // 8-bit: each level is filtered from the unrounded values of the one above (level 0's
  // decoded codes), then rounded to codes; alpha by its own (linear) table.
  const std::array<float, 256>& colour = code_values(texture.encoding);
  const std::array<float, 256>& linear = code_values(TextureEncoding::linear);
  const NearestCode& nearest_colour = nearest_code(texture.encoding);
  const NearestCode& nearest_linear = nearest_code(TextureEncoding::linear);
  std::array<const float*, 4> channel_values{};  // per channel: its code → value table
  for (int k = 0; k < c; ++k)
    channel_values[static_cast<std::size_t>(k)] = is_alpha_channel(k, c) ? linear.data() : colour.data();
  const std::uint8_t* codes = texture.codes.data();
  std::vector<float> fine_values;  // the unrounded values of the level above, below level 0
  while (pyramid.levels.back().width > 1 || pyramid.levels.back().height > 1) {
    const MipLevel& fine = pyramid.levels.back();
    MipLevel coarse;
    coarse.width = std::max(1, fine.width / 2);
    coarse.height = std::max(1, fine.height / 2);
    std::vector<float> values =
        fine_values.empty()
            ? box_filter_level([&](std::size_t t, int k) { return channel_values[k][codes[t * c + k]]; }, fine.width,
                               fine.height, coarse.width, coarse.height, c)
            : box_filter_level([&](std::size_t t, int k) { return fine_values[t * c + k]; }, fine.width, fine.height,
                               coarse.width, coarse.height, c);
    coarse.codes.resize(values.size());
    for (std::size_t t = 0; t < values.size(); t += static_cast<std::size_t>(c))
      for (int k = 0; k < c; ++k)
        coarse.codes[t + k] = is_alpha_channel(k, c) ? nearest_linear(values[t + k]) : nearest_colour(values[t + k]);
    coarse.colour_values = colour.data();
    fine_values = std::move(values);
    pyramid.levels.push_back(std::move(coarse));
  }
  return pyramid;
}

float mip_level_from_uv_derivatives(const MipPyramid& pyramid, Vec2f duv_dx, Vec2f duv_dy) {
  const MipLevel& base = pyramid.levels.front();
  const float w = static_cast<float>(base.width), h = static_cast<float>(base.height);
  const float lx = std::hypot(duv_dx.x * w, duv_dx.y * h), ly = std::hypot(duv_dy.x * w, duv_dy.y * h);
  const float footprint = std::max(lx, ly);
  return footprint > 0.0f && std::isfinite(footprint) ? std::log2(footprint) : 0.0f;
}

float mip_level_from_ray_cone(const MipPyramid& pyramid, float cone_width, float cos_theta, float uv_area,
                              float world_area) {
  const MipLevel& base = pyramid.levels.front();
  const float texel_area = static_cast<float>(base.width) * static_cast<float>(base.height) * std::abs(uv_area);
  const float cos_abs = std::max(std::abs(cos_theta), 1e-4f);  // grazing: cap the footprint
  const float footprint = std::abs(cone_width) / cos_abs * std::sqrt(texel_area / std::abs(world_area));
  return footprint > 0.0f && std::isfinite(footprint) ? std::log2(footprint) : 0.0f;
}

TexelRgba sample_trilinear(const MipPyramid& pyramid, Vec2f uv, float level_of_detail) {
  const float max_level = static_cast<float>(pyramid.levels.size() - 1);
  const float lod = std::isfinite(level_of_detail) ? std::clamp(level_of_detail, 0.0f, max_level) : 0.0f;
  const int l0 = static_cast<int>(std::floor(lod));
  const int l1 = std::min(l0 + 1, static_cast<int>(max_level));
  const float t = lod - static_cast<float>(l0);
  const TexelRgba a = sample_bilinear(pyramid.levels[l0], pyramid.channels, uv, pyramid.wrap_u, pyramid.wrap_v);
  if (t == 0.0f || l0 == l1) return a;
  const TexelRgba b = sample_bilinear(pyramid.levels[l1], pyramid.channels, uv, pyramid.wrap_u, pyramid.wrap_v);
  TexelRgba r;
  for (int k = 0; k < 4; ++k) r[k] = (1 - t) * a[k] + t * b[k];
  return r;
}

}  // namespace prism
