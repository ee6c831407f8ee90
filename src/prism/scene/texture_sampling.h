#pragma once
// Texture lookups: wrap modes, bilinear filtering and a box-filtered MIP pyramid with
// trilinear lookup at a level of detail from the ray's footprint (uv derivatives of ray
// differentials, or a ray cone).
//
// Coordinates follow glTF: u runs left to right, v top to bottom (row 0 of the image is
// v = 0); texel (x, y) covers [x, x+1]/width × [y, y+1]/height, so its centre is at
// ((x + ½)/width, (y + ½)/height). The texture's uv transform (offset, scale, rotation) is
// applied by apply_uv_transform, not by the samplers.
#include <array>
#include <cstdint>
#include <vector>

#include "prism/core/vec.h"
#include "prism/scene/texture.h"

namespace prism {

// Grey expands to (g, g, g, 1), grey+alpha to (g, g, g, a), RGB to (r, g, b, 1).
using TexelRgba = std::array<float, 4>;

// One level of a pyramid, in its image's storage: floats, or 8-bit codes (then
// `colour_values` is set: the code → linear value table of its colour channels; alpha is
// decoded linearly, as in TextureImage). Level 0 of a Radiance image is its RGBE texels
// (borrowed_rgbe), level 0 of a half-float image its halves (borrowed_halves); their
// coarser levels are floats.
struct MipLevel {
  int width = 0, height = 0;
  std::vector<float> texels;        // channels per texel, as in TextureImage; empty where borrowed
  const float* borrowed = nullptr;  // level 0 of a pyramid: its TextureImage's texels, not copied
  std::vector<std::uint8_t> codes;  // the same for 8-bit levels
  const std::uint8_t* borrowed_codes = nullptr;
  const float* colour_values = nullptr;
  const std::uint8_t* borrowed_rgbe = nullptr;  // level 0 of an RGBE image: 4 bytes per texel
  const std::uint16_t* borrowed_halves = nullptr;  // level 0 of a half-float image: channels per texel
  const float* data() const { return borrowed != nullptr ? borrowed : texels.data(); }
  const std::uint8_t* code_data() const { return borrowed_codes != nullptr ? borrowed_codes : codes.data(); }
  bool has_codes() const { return colour_values != nullptr; }
  bool has_rgbe() const { return borrowed_rgbe != nullptr; }
  bool has_halves() const { return borrowed_halves != nullptr; }
  // Bytes this level holds itself (a borrowed level 0 holds none).
  std::size_t owned_bytes() const { return texels.size() * sizeof(float) + codes.size(); }
};

struct MipPyramid {
  int channels = 0;
  TextureWrap wrap_u = TextureWrap::repeat, wrap_v = TextureWrap::repeat;
  std::vector<MipLevel> levels;  // levels[0] is the full image; the last is 1×1
};

// Maps an integer texel coordinate into [0, size) by the wrap mode.
int wrap_texel_coordinate(int i, int size, TextureWrap wrap);

Vec2f apply_uv_transform(const TextureImage& texture, Vec2f uv);

TexelRgba texel_fetch(const MipLevel& level, int channels, int x, int y, TextureWrap wrap_u, TextureWrap wrap_v);
TexelRgba sample_bilinear(const MipLevel& level, int channels, Vec2f uv, TextureWrap wrap_u, TextureWrap wrap_v);
TexelRgba sample_bilinear(const TextureImage& texture, Vec2f uv);

// Each level halves the previous one's size (rounding down, at least 1) and averages the
// 2×2 texels it covers (a box filter). With an odd size the last coarse texel averages the
// three fine texels left over, so no texel is dropped. Level 0 is the texture's own
// texels, borrowed rather than copied (a 2048² RGB texture is 12 MB of codes, or 48 MB
// of floats), so the pyramid must not outlive the texture; a temporary is refused at
// compile time. The levels of an 8-bit image are 8-bit too, as on GPUs: each is averaged
// from the unrounded linear values of the level above and stored as the code whose value
// is nearest (within half a code step of the average: 0.2 % of full scale for linear codes,
// at most 0.43 % for sRGB ones, whose steps are widest near white).
MipPyramid build_mip_pyramid(const TextureImage& texture);
MipPyramid build_mip_pyramid(TextureImage&& texture) = delete;
// Level 0 alone, borrowed: for textures read texel by texel (environment maps), which
// filtered lookups never reach.
MipPyramid base_level_pyramid(const TextureImage& texture);
MipPyramid base_level_pyramid(TextureImage&& texture) = delete;

// Level of detail λ (0 = finest) from the screen-space uv derivatives of a ray
// differential: log2 of the longer of the two texel-space footprint axes.
float mip_level_from_uv_derivatives(const MipPyramid& pyramid, Vec2f duv_dx, Vec2f duv_dy);

// Level of detail from a ray cone (Akenine-Möller et al. 2021, "Improved shader and texture
// level of detail using ray cones", JCGT 10(1)): the cone's width at the hit divided by
// |cos θ| is the footprint in world units; sqrt(texel area / world area) of the hit
// triangle converts it to texels. λ = log2(width/|cos θ| · sqrt(w·h·uv_area / world_area)).
float mip_level_from_ray_cone(const MipPyramid& pyramid, float cone_width, float cos_theta, float uv_area,
                              float world_area);

// Trilinear: bilinear in the two levels around λ (clamped to the pyramid), blended linearly.
TexelRgba sample_trilinear(const MipPyramid& pyramid, Vec2f uv, float level_of_detail);

}  // namespace prism
