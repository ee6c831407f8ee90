#pragma once
// Radiance picture files (.hdr; Ward 1991, "Real Pixels", Graphics Gems II; the Radiance
// reference manual's file format section): a text header ("#?RADIANCE" or "#?RGBE", lines
// of variables up to an empty line, FORMAT=32-bit_rle_rgbe required), a resolution line
// ("-Y height +X width": rows top to bottom, the only orientation read), then scanlines of
// RGBE texels — three 8-bit mantissas and a shared exponent — flat, or in the "new" run-length
// encoding (each scanline starts 2, 2, width / 256, width % 256, then the four components
// one after the other as runs (count > 128: count − 128 copies of one byte) and dumps
// (count bytes as they are)).
//
// Read here rather than by stb_image, whose reader converts to floats (12 bytes per texel
// while it decodes, 100 MB for a 4096 × 2048 sky, beside the 4 kept) and loops forever on a
// scanline cut short. Which files are read, and the texels, are stb_image's: files whose
// width is below 8 or above 32767 are flat; a scanline that does not start 2, 2 (with a
// width below 32768) makes the rest of the file flat texels from the image's first.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace prism {

struct RadianceHeader {
  long width = 0, height = 0;
  std::size_t data_offset = 0;  // where the first scanline starts
};

// Throws IoError "cannot read image '<name>': <why>" for a header that is not a Radiance
// RGBE header.
RadianceHeader read_radiance_header(std::span<const unsigned char> bytes, std::string_view name);

// The texels, 4 bytes each (r, g, b, exponent), row 0 at the top. `header` must come from
// read_radiance_header(bytes) and have positive dimensions. Throws IoError for a truncated
// file and for corrupt run-length data.
std::vector<std::uint8_t> read_radiance_texels(std::span<const unsigned char> bytes, const RadianceHeader& header,
                                               std::string_view name);

}  // namespace prism
