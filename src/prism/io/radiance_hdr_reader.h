#pragma once
// Radiance picture files (.hdr; Ward 1991, "Real Pixels", Graphics Gems II; the Radiance
// reference manual's file format section): a text header ("#?RADIANCE" or "#?RGBE", lines
// of variables up to an empty line, FORMAT=32-bit_rle_rgbe or 32-bit_rle_xyze required), a
// resolution line ("-Y height +X width": rows top to bottom, each left to right, as Radiance
// writes; the seven flipped and rotated orders are read too), then scanlines of RGBE texels — three 8-bit mantissas and a shared exponent — flat, or in the "new" run-length
// encoding (each scanline starts 2, 2, length / 256, length % 256, then the four components
// one after the other as runs (count > 128: count − 128 copies of one byte) and dumps
// (count bytes as they are)).
//
// Read here rather than by stb_image, whose reader converts to floats (12 bytes per texel
// while it decodes, 100 MB for a 4096 × 2048 sky, beside the 4 kept) and loops forever on a
// scanline cut short. Which files are read, and the texels, are stb_image's: files whose
// width is below 8 or above 32767 are flat; a scanline that does not start 2, 2 (with a
// width below 32768) makes the rest of the file flat texels from the image's first.
//
// The header variables that say what the texels mean, which stb_image ignores (the
// Radiance manual, "Radiance File Formats", picture file header):
//   FORMAT=32-bit_rle_xyze  the texels are CIE XYZ, not RGB (the same encoding). Radiance
//                           holds XYZ relative to the equal-energy white (its RGB white
//                           (1,1,1) is XYZ (1,1,1)).
//   EXPOSURE= e             the texels were multiplied by e; radiance is texel / e. The
//                           lines are cumulative: their product is the factor.
//   COLORCORR= r g b        the same per channel, also cumulative.
//   PRIMARIES= rx ry gx gy bx by wx wy
//                           the RGB primaries and white as CIE xy. Without the line the
//                           file is taken as Rec.709/D65, as every HDRI producer and
//                           renderer does (Radiance's own default, green 0.29 0.60 and
//                           white E, is not what files in circulation hold). Photoshop
//                           writes "PRIMARIES=0 0 0 0 0 0 0 0", meaning none: read as
//                           absent.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/core/vec.h"

namespace prism {

struct RadianceHeader {
  long width = 0, height = 0;   // of the picture as seen: rows top to bottom, left to right
  // The resolution line's order, "-Y H +X W" (rows from the top, each left to right) when
  // all are false: scanlines are columns ("±X W ±Y H"), run or step from the bottom ("+Y"),
  // from the right ("-X"). read_radiance_texels returns rows top to bottom whatever it is.
  bool columns = false, bottom_up = false, right_to_left = false;
  std::size_t data_offset = 0;  // where the first scanline starts
  bool xyz = false;             // FORMAT=32-bit_rle_xyze
  double exposure = 1.0;        // the product of the EXPOSURE= lines
  std::array<double, 3> color_correction{1.0, 1.0, 1.0};  // the product of the COLORCORR= lines
  std::optional<color::Primaries> primaries;               // a PRIMARIES= line, unless all zero
};

// Throws IoError "cannot read image '<name>': <why>" for a header that is not a Radiance
// RGBE or XYZE header, and for a variable above whose value does not read (with its line
// number): an EXPOSURE or COLORCORR that is not a positive finite number, a PRIMARIES line
// that is not eight numbers or names no RGB space.
RadianceHeader read_radiance_header(std::span<const unsigned char> bytes, std::string_view name);

// What the texels are by the header: CIE XYZ relative to E for XYZE (Radiance's XYZ white),
// RGB in the PRIMARIES, or Rec.709 without that line. `name` names a PRIMARIES space.
color::ColorSpace radiance_color_space(const RadianceHeader& header, std::string_view name);
// Whether EXPOSURE or COLORCORR lines scale the texels.
bool radiance_texels_scaled(const RadianceHeader& header);
// Per channel, what a texel is multiplied by to be radiance: 1 / (EXPOSURE · COLORCORR).
Vec3d radiance_texel_factors(const RadianceHeader& header);

// The texels, 4 bytes each (r, g, b, exponent), row 0 at the top. `header` must come from
// read_radiance_header(bytes) and have positive dimensions. Throws IoError for a truncated
// file and for corrupt run-length data.
std::vector<std::uint8_t> read_radiance_texels(std::span<const unsigned char> bytes, const RadianceHeader& header,
                                               std::string_view name);

// RGBE texels (read_radiance_texels) as float RGB, each channel times `factors`.
std::vector<float> radiance_texels_as_floats(const std::vector<std::uint8_t>& rgbe, const Vec3d& factors);

// A whole Radiance picture as radiance: float pixels (the header's factors divided out) in
// its colour space (radiance_color_space). Throws IoError as the two readers above do.
struct RadianceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 × width × height, row 0 at the top
  color::ColorSpace space;
};
RadianceImage read_radiance_image(std::span<const unsigned char> bytes, std::string_view name);

}  // namespace prism
