#pragma once
// Texture images as loaded: linear floating-point texels (sRGB-encoded colour textures are
// decoded at load time), with the addressing the material asked for.
#include <cstdint>
#include <string>
#include <vector>

#include "prism/core/vec.h"

namespace prism {

enum class TextureWrap : std::uint8_t { repeat, clamp, mirror };

struct TextureImage {
  std::string name;  // file name or generated name, for messages and `prism info`
  int width = 0, height = 0;
  int channels = 0;            // 1 to 4, interleaved
  std::vector<float> texels;   // linear, width × height × channels, row 0 at the top
  TextureWrap wrap_u = TextureWrap::repeat, wrap_v = TextureWrap::repeat;
  // KHR_texture_transform / pbrt uv mapping: uv' = offset + scale ⊙ rotate(uv)
  float offset_u = 0.0f, offset_v = 0.0f, scale_u = 1.0f, scale_v = 1.0f, rotation_radians = 0.0f;

  std::size_t memory_bytes() const { return texels.size() * sizeof(float); }
};

// Texel (x, y), row 0 at the top, as RGB: grey and grey+alpha images carry their value in
// the first channel, which stands for all three (alpha is not colour).
inline Vec3f texel_rgb(const TextureImage& t, int x, int y) {
  const float* p = &t.texels[(static_cast<std::size_t>(y) * t.width + x) * t.channels];
  return t.channels >= 3 ? Vec3f(p[0], p[1], p[2]) : Vec3f(p[0]);
}

}  // namespace prism
