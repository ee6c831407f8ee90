#pragma once
// Which Radiance scanlines are run-length encoded (the "new" RLE of Radiance's picture
// format, Ward 1991, "Real Pixels", Graphics Gems II): those from 8 to 32767 texels wide.
// A scanline starts with the bytes 2, 2 and its width in 15 bits, so wider ones cannot say
// their width, and narrower ones gain nothing; both are stored flat, 4 bytes a texel. The
// reader (io/radiance_hdr_reader.h) and the writer (io/radiance_hdr_writer.h) keep this one rule.
#include <cstddef>

namespace prism {

constexpr bool radiance_scanline_is_run_length(std::size_t width) { return width >= 8 && width < 32768; }

}  // namespace prism
