#pragma once
// Texture images as loaded, with the addressing the material asked for. Texels are linear
// values: floats (EXR files, 16-bit PNGs, images made in code), the 8-bit codes of a PNG
// or JPEG kept as they are and decoded at each lookup through a 256-entry table (the sRGB
// EOTF for colour textures, code/255 for data textures and alpha), the values decoding
// them to floats at load time gave, in a quarter of the memory; or the shared-exponent
// texels of a Radiance .hdr file as it holds them (Ward 1991, "Real Pixels", Graphics Gems
// II; io/radiance_hdr_reader.h), 4 bytes per RGB texel instead of 12, decoded at each lookup
// to exactly the floats stb_image's reader gives.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "prism/core/half_float.h"
#include "prism/core/vec.h"
#include "prism/scene/color_picker_space.h"

namespace prism {

enum class TextureWrap : std::uint8_t { repeat, clamp, mirror };

// How 8/16-bit codes map to linear values. Colour textures (base colour, emission) are
// sRGB-encoded by convention and decoded with the IEC 61966-2-1 EOTF; data textures
// (roughness/metallic, normals) are linear codes / (2^bits - 1). Float formats (EXR, .hdr)
// are linear whatever is asked. Alpha is always linear.
enum class TextureEncoding : std::uint8_t { srgb, linear };

namespace detail {
// Filled before main (texture.cpp); no static initialiser decodes a texture.
extern const std::array<float, 256> kSrgbCodeValues, kLinearCodeValues;
}  // namespace detail

// The linear value of each 8-bit code under `encoding`, rounded to float once. Inline and
// without a guard: lookups ask for it at every texel.
inline const std::array<float, 256>& code_values(TextureEncoding encoding) {
  return encoding == TextureEncoding::srgb ? detail::kSrgbCodeValues : detail::kLinearCodeValues;
}

namespace detail {
// 2^(e − 136) for exponent byte e > 0, and 0 for e = 0 (stb_image's RGBE conversion).
extern const std::array<float, 256> kRgbeExponentScales;
}  // namespace detail

// One channel of an RGBE texel: mantissa · 2^(exponent − 136), as stb_image computes it
// (an 8-bit mantissa times a power of two: exact in float).
inline float rgbe_value(std::uint8_t mantissa, std::uint8_t exponent) {
  return static_cast<float>(mantissa) * detail::kRgbeExponentScales[exponent];
}

// Whether channel `channel` of a `channels`-channel image is alpha (the 2nd of grey+alpha,
// the 4th of RGBA), which is linear whatever the colour channels' encoding.
constexpr bool is_alpha_channel(int channel, int channels) {
  return (channels == 2 || channels == 4) && channel == channels - 1;
}

// What a texture's channels hold: colours (base, emission, sheen, specular colour,
// environment), which have primaries, or data (normals, roughness, heights, masks).
// Colour texels are linear Rec.709: an OpenEXR's are converted from the primaries its
// chromaticities attribute names and what Rec.709 cannot hold is clipped. A wide-gamut
// material's base colour (Material::base_color_space) asks for its own space instead
// (color_acescg, color_rec2020): an OpenEXR's texels are then converted into that space,
// keeping the colours outside Rec.709 that it holds. color_own_gamut keeps an OpenEXR in
// the first of Rec.709, Rec.2020 and ACEScg whose gamut holds its primaries (pbrt-v4's
// image textures keep their file's colour space; the material then takes the texture's,
// pbrt_parser.cpp; every loader's environment maps, whose radiance the renderer takes from
// that space, render/color_context.h). 8-bit and .hdr images have no primaries attribute here and stay
// Rec.709 whatever is asked (TextureImage::texel_space says where texels are).
enum class TextureContent : std::uint8_t { color, data, color_acescg, color_rec2020, color_own_gamut };

// The colour content whose OpenEXR texels are in `space`.
constexpr TextureContent color_content_in(ColorPickerSpace space) {
  switch (space) {
    case ColorPickerSpace::acescg: return TextureContent::color_acescg;
    case ColorPickerSpace::rec2020: return TextureContent::color_rec2020;
    case ColorPickerSpace::srgb: break;
  }
  return TextureContent::color;
}
constexpr bool is_color_content(TextureContent c) { return c != TextureContent::data; }
// The space a colour content asks for (srgb for color, and for data, which has none;
// color_own_gamut's depends on the file).
constexpr ColorPickerSpace requested_space(TextureContent c) {
  switch (c) {
    case TextureContent::color_acescg: return ColorPickerSpace::acescg;
    case TextureContent::color_rec2020: return ColorPickerSpace::rec2020;
    case TextureContent::color:
    case TextureContent::color_own_gamut:
    case TextureContent::data: break;
  }
  return ColorPickerSpace::srgb;
}

struct TextureImage {
  std::string name;  // file name or generated name, for messages and `prism info`
  int width = 0, height = 0;
  int channels = 0;  // 1 to 4, interleaved
  // The texels, width × height × channels, row 0 at the top: `texels` for float images,
  // `codes` (with `encoding`) for 8-bit ones, `rgbe` (r, g, b mantissas and the shared
  // exponent, 4 bytes per texel; channels = 3) for Radiance .hdr ones (floats where a colour
  // texture's were converted, texture_file.h), `halves` (IEEE
  // binary16 bits, linear) for OpenEXR images stored in half floats. Three are empty.
  std::vector<float> texels;
  std::vector<std::uint8_t> codes;
  TextureEncoding encoding = TextureEncoding::linear;  // of `codes`
  std::vector<std::uint8_t> rgbe{};
  std::vector<std::uint16_t> halves{};
  TextureWrap wrap_u = TextureWrap::repeat, wrap_v = TextureWrap::repeat;
  // KHR_texture_transform / pbrt uv mapping: uv' = offset + scale ⊙ rotate(uv)
  float offset_u = 0.0f, offset_v = 0.0f, scale_u = 1.0f, scale_v = 1.0f, rotation_radians = 0.0f;

  // The primaries of a colour texture's RGB texels: Rec.709 (srgb), or the wide-gamut
  // space an OpenEXR or Radiance picture was read into for a wide-gamut base colour or a
  // sky (TextureContent).
  ColorPickerSpace texel_space = ColorPickerSpace::srgb;
  // Set when a colour texture in other primaries than Rec.709 was converted at load (an
  // OpenEXR's chromaticities, a Radiance picture's PRIMARIES or XYZE format), when a
  // Radiance header's EXPOSURE or COLORCORR was divided out, or when texels fell outside the
  // gamut they were converted into and were clipped: what was done and how many, for the
  // loader's warnings. Empty otherwise.
  std::string primaries_note{};

  bool has_codes() const { return !codes.empty(); }
  bool has_rgbe() const { return !rgbe.empty(); }
  bool has_halves() const { return !halves.empty(); }
  std::size_t sample_count() const {
    return has_codes() ? codes.size() : has_rgbe() ? rgbe.size() / 4 * 3 : has_halves() ? halves.size() : texels.size();
  }
  // Sample i (texel i / channels, channel i % channels) as a linear value.
  float value(std::size_t i) const {
    if (has_codes()) {
      const bool alpha = is_alpha_channel(static_cast<int>(i % static_cast<std::size_t>(channels)), channels);
      return code_values(alpha ? TextureEncoding::linear : encoding)[codes[i]];
    }
    if (has_rgbe()) return rgbe_value(rgbe[i / 3 * 4 + i % 3], rgbe[i / 3 * 4 + 3]);
    if (has_halves()) return half_bits_to_float(halves[i]);
    return texels[i];
  }
  // Every sample's linear value, in order (the float texels, or the codes decoded).
  std::vector<float> linear_values() const;
  std::size_t memory_bytes() const {
    return texels.size() * sizeof(float) + codes.size() + rgbe.size() + halves.size() * sizeof(std::uint16_t);
  }
};

// Every colour channel's linear value v replaced by f(v) in place, alpha kept, held as floats
// from then on (a mapped sRGB code is no code: 4 bytes a sample instead of 1); `what` is
// appended to the image's name, for messages.
void map_texture_values(TextureImage& image, const std::function<float(float)>& f, const std::string& what);

// pbrt-v4's imagemap "invert" (ImageTexture: v ↦ max(0, 1 − scale · v), the texture's scale
// applied first).
void invert_texture_values(TextureImage& image, float scale);

// Texel (x, y), row 0 at the top, as RGB: grey and grey+alpha images carry their value in
// the first channel, which stands for all three (alpha is not colour).
inline Vec3f texel_rgb(const TextureImage& t, int x, int y) {
  const std::size_t texel = static_cast<std::size_t>(y) * t.width + x, i = texel * t.channels;
  if (t.has_rgbe()) {
    const std::uint8_t* p = &t.rgbe[texel * 4];
    return {rgbe_value(p[0], p[3]), rgbe_value(p[1], p[3]), rgbe_value(p[2], p[3])};
  }
  if (t.has_halves()) {
    const std::uint16_t* p = &t.halves[i];
    return t.channels >= 3 ? Vec3f(half_bits_to_float(p[0]), half_bits_to_float(p[1]), half_bits_to_float(p[2]))
                           : Vec3f(half_bits_to_float(p[0]));
  }
  if (!t.has_codes()) {
    const float* p = &t.texels[i];
    return t.channels >= 3 ? Vec3f(p[0], p[1], p[2]) : Vec3f(p[0]);
  }
  const std::uint8_t* p = &t.codes[i];
  const std::array<float, 256>& colour = code_values(t.encoding);  // the first three channels are never alpha
  return t.channels >= 3 ? Vec3f(colour[p[0]], colour[p[1]], colour[p[2]]) : Vec3f(colour[p[0]]);
}

}  // namespace prism
