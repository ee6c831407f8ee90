#include "prism/scene/texture_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

// The texel at wrapped coordinates (xi, yi) ∈ [0, width) × [0, height). Always inlined,
// like wrap_reduced_coordinate: GCC otherwise calls both out of line from bilinear()'s
// four sites, and the texel comes back through memory.
[[gnu::always_inline]] inline TexelRgba texel_at_index(const float* texels, int width, int channels, int xi, int yi) {
  const float* p = texels + (static_cast<std::size_t>(yi) * width + xi) * channels;
  switch (channels) {
    case 1: return {p[0], p[0], p[0], 1.0f};
    case 2: return {p[0], p[0], p[0], p[1]};
    case 3: return {p[0], p[1], p[2], 1.0f};
    default: return {p[0], p[1], p[2], p[3]};
  }
}

TexelRgba fetch(const float* texels, int width, int height, int channels, int x, int y, TextureWrap wrap_u,
                TextureWrap wrap_v) {
  return texel_at_index(texels, width, channels, wrap_texel_coordinate(x, width, wrap_u),
                        wrap_texel_coordinate(y, height, wrap_v));
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

TexelRgba bilinear(const float* texels, int width, int height, int channels, Vec2f uv, TextureWrap wrap_u,
                   TextureWrap wrap_v) {
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = {0.0f, 0.0f};
  // Texel centres sit at half-integers: shift so that integer coordinates are centres.
  const double x = static_cast<double>(uv.x) * width - 0.5, y = static_cast<double>(uv.y) * height - 0.5;
  const double x0 = floor_exact(x), y0 = floor_exact(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const int ix = reduce_coordinate(x0, width, wrap_u), iy = reduce_coordinate(y0, height, wrap_v);
  // Each column and row wrapped once, not once per texel.
  const int x_lo = wrap_reduced_coordinate(ix, width, wrap_u), x_hi = wrap_reduced_coordinate(ix + 1, width, wrap_u);
  const int y_lo = wrap_reduced_coordinate(iy, height, wrap_v), y_hi = wrap_reduced_coordinate(iy + 1, height, wrap_v);
  const TexelRgba a = texel_at_index(texels, width, channels, x_lo, y_lo);
  const TexelRgba b = texel_at_index(texels, width, channels, x_hi, y_lo);
  const TexelRgba c = texel_at_index(texels, width, channels, x_lo, y_hi);
  const TexelRgba d = texel_at_index(texels, width, channels, x_hi, y_hi);
  TexelRgba r;
  for (int k = 0; k < 4; ++k) r[k] = (1 - fy) * ((1 - fx) * a[k] + fx * b[k]) + fy * ((1 - fx) * c[k] + fx * d[k]);
  return r;
}

}  // namespace

TexelRgba texel_fetch(const MipLevel& level, int channels, int x, int y, TextureWrap wrap_u, TextureWrap wrap_v) {
  return fetch(level.data(), level.width, level.height, channels, x, y, wrap_u, wrap_v);
}

TexelRgba sample_bilinear(const MipLevel& level, int channels, Vec2f uv, TextureWrap wrap_u, TextureWrap wrap_v) {
  return bilinear(level.data(), level.width, level.height, channels, uv, wrap_u, wrap_v);
}

TexelRgba sample_bilinear(const TextureImage& texture, Vec2f uv) {
  return bilinear(texture.texels.data(), texture.width, texture.height, texture.channels,
                  apply_uv_transform(texture, uv), texture.wrap_u, texture.wrap_v);
}

MipPyramid build_mip_pyramid(const TextureImage& texture) {
  MipPyramid pyramid;
  pyramid.channels = texture.channels;
  pyramid.wrap_u = texture.wrap_u;
  pyramid.wrap_v = texture.wrap_v;
  pyramid.levels.push_back({texture.width, texture.height, {}, texture.texels.data()});
  const int c = texture.channels;
  while (pyramid.levels.back().width > 1 || pyramid.levels.back().height > 1) {
    const MipLevel& fine = pyramid.levels.back();
    MipLevel coarse;
    coarse.width = std::max(1, fine.width / 2);
    coarse.height = std::max(1, fine.height / 2);
    coarse.texels.assign(static_cast<std::size_t>(coarse.width) * coarse.height * c, 0.0f);
    for (int y = 0; y < coarse.height; ++y) {
      // Fine rows covered by coarse row y: 2y, 2y+1, and 2y+2 for the last row of an odd size.
      const int y_begin = std::min(2 * y, fine.height - 1);
      const int y_end = (y == coarse.height - 1) ? fine.height : std::min(2 * y + 2, fine.height);
      for (int x = 0; x < coarse.width; ++x) {
        const int x_begin = std::min(2 * x, fine.width - 1);
        const int x_end = (x == coarse.width - 1) ? fine.width : std::min(2 * x + 2, fine.width);
        float* out = coarse.texels.data() + (static_cast<std::size_t>(y) * coarse.width + x) * c;
        for (int fy = y_begin; fy < y_end; ++fy)
          for (int fx = x_begin; fx < x_end; ++fx)
            for (int k = 0; k < c; ++k) out[k] += fine.data()[(static_cast<std::size_t>(fy) * fine.width + fx) * c + k];
        const float n = static_cast<float>((y_end - y_begin) * (x_end - x_begin));
        for (int k = 0; k < c; ++k) out[k] /= n;
      }
    }
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
