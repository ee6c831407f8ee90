#pragma once
// What a PNG or JPEG says of its colours, read from its tags, for colour textures:
//   PNG (W3C PNG Third Edition §11.3.2, in its order of precedence): cICP (ITU-T H.273
//     code points for primaries and transfer), iCCP (an embedded ICC profile), sRGB, and
//     cHRM and gAMA (chromaticities and a power law);
//   JPEG: an ICC profile in APP2 "ICC_PROFILE" segments (ICC.1 Annex B.4).
// Without a tag an image is sRGB, as the PNG and JPEG/JFIF conventions and every renderer
// take it. ICC profiles are read for their matrix/TRC model (color/icc_profile_reader.h).
//
// A tag that cannot be used (an ICC profile of lookup tables only, a cICP code point
// H.273 does not define, a chunk of the wrong size) is passed over for the next one in
// precedence, and `passed_over` says which and why, for the loader's warning. cICP's PQ
// and HLG transfers are refused (IoError): they are HDR signals, not texture code values.
#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "prism/color/color_space.h"
#include "prism/color/icc_profile_reader.h"
#include "prism/core/mat3.h"

namespace prism {

struct ImageColorTags {
  // No tag, or tags that say sRGB exactly (the sRGB chunk, cICP 1/13, gAMA 1/2.2 without
  // other chromaticities, an ICC profile within 0.5 of a code of sRGB): 8-bit codes are
  // then kept and decoded through the sRGB table (scene/texture.h).
  bool srgb = true;
  std::string source;                      // "ICC profile 'Display P3'", "cICP 12/13", ...; "" without tags
  std::array<color::IccCurve, 3> curves;   // code in [0, 1] → linear, per colour channel (grey: [0])
  bool narrow_range = false;               // cICP's video range: codes 16..235 (× 2^(bits − 8)) span [0, 1]
  std::optional<color::Primaries> primaries;  // primaries by chromaticities (cICP, cHRM)
  std::optional<Mat3> pcs_colorants;          // or by ICC colorants: linear RGB → XYZ (D50)
  std::string passed_over;                 // tags present and not used, and why; "" for none
};

// Whether the PNG or JPEG file at `path` has tags that may make its colour texels depend
// on their use (cICP, iCCP, cHRM, gAMA; an APP2 ICC profile), from its chunk or segment
// headers alone, which lie before the image data. False for other files and files that do
// not read (decoding them reports why).
bool image_file_has_color_tags(const std::filesystem::path& path);

// `name` only for messages. Throws IoError for a cICP transfer a texture cannot take.
ImageColorTags read_png_color_tags(std::span<const unsigned char> png, std::string_view name);
ImageColorTags read_jpeg_color_tags(std::span<const unsigned char> jpeg, std::string_view name);

// Linear RGB of the file → linear RGB of `target`: Bradford between the whites for
// chromaticities (as OpenEXR's are converted), and for ICC colorants the profile
// connection space's way, into XYZ (D50) and out through `target`'s colorants adapted to
// D50 with Bradford (ICC.1 Annex E, color/icc_profile.h). Identity for an sRGB file whose
// target is sRGB.
Mat3 image_color_conversion(const ImageColorTags& tags, const color::ColorSpace& target);

// The linear value of code `code` of a `max_code` (255, 65535) image's colour channel
// `channel` (grey: 0) under its tags.
double decode_tagged_code(const ImageColorTags& tags, int channel, unsigned code, unsigned max_code);

}  // namespace prism
