#pragma once
// Radiance picture (.hdr) output: linear scene-referred pixels as RGBE or XYZE texels
// (Ward 1991, "Real Pixels", Graphics Gems II; the Radiance manual's picture format), the
// format every HDRI tool reads. What Prism's own reader (io/radiance_hdr_reader.h) reads back:
//   - the header names what the texels are: FORMAT=32-bit_rle_xyze for CIE XYZ relative to
//     the equal-energy white (the spectral film's space, so a spectral render is written
//     without a conversion and without clipping), otherwise FORMAT=32-bit_rle_rgbe and a
//     PRIMARIES line with the space's chromaticities (Rec.709 too, so that no reader
//     guesses);
//   - texels are rounded to the nearest RGBE value (three 8-bit mantissas under the largest
//     channel's exponent: each channel within half a step of 2^(e − 8) of its value, e the
//     exponent of the largest), where Ward's encoder truncates; readers decode m · 2^(e − 136)
//     as stb_image does (Radiance's own adds half a step);
//   - scanlines are run-length encoded ("new" RLE: 2, 2, width / 256, width % 256, then each
//     component as runs and dumps) for widths 8 to 32767, flat otherwise.
// RGBE holds no negative numbers: channels below 0 (colours outside the space's gamut) and
// non-finite ones are written as 0, and counted.
#include <cstddef>
#include <filesystem>
#include <string_view>

#include "prism/color/color_space.h"
#include "prism/io/image.h"

namespace prism {

struct RadianceWriteReport {
  std::size_t clipped_pixels = 0;  // pixels with a channel below 0 or not finite, written as 0
};

// Writes `image`, whose pixels are in `space` (an RGB space, or an XYZ one relative to E),
// atomically (io/atomic_file.h). `software` goes into the SOFTWARE line. Throws IoError
// when the file cannot be written, UsageError for an XYZ space with another white (Radiance
// XYZ is relative to E) or an image whose size the format cannot hold.
RadianceWriteReport write_radiance_hdr(const std::filesystem::path& path, const ImageRgbF& image,
                                       const color::ColorSpace& space, std::string_view software);

// One pixel as RGBE (or XYZE) bytes, rounded to nearest; negative and non-finite channels
// as 0. Exposed for tests.
struct RgbeBytes {
  unsigned char r = 0, g = 0, b = 0, e = 0;
};
RgbeBytes encode_rgbe(float r, float g, float b);

}  // namespace prism
