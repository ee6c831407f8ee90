#pragma once
// Which colour tags a display-referred PNG gets, in one place for `prism render/tonemap`
// and the viewer's Save: the sRGB chunk for sRGB itself; otherwise, for SDR curves, an ICC
// v4 matrix/TRC profile of the output primaries (color/icc_profile.h) plus cICP where
// ITU-T H.273 has code points for the primaries. (PQ outputs are tagged with cICP, mDCv
// and cLLi by the caller: an ICC matrix/TRC profile cannot describe absolute PQ light.)
#include <cstdint>

#include "prism/color/color_space.h"
#include "prism/color/icc_profile.h"
#include "prism/io/png_hdr.h"

namespace prism {

// H.273 ColourPrimaries of a space: 1 (BT.709/sRGB), 9 (BT.2020), 12 (P3-D65), or 0 when it
// has none (Adobe RGB, DCI-P3 with its own white, user primaries). Compared by xy (1e-4).
std::uint8_t cicp_color_primaries(const color::ColorSpace& space);

// Tags for 8/16-bit SDR code values that decode with `curve` to linear `primaries`.
PngColorMetadata sdr_png_color_metadata(const color::ColorSpace& primaries, color::IccToneCurve curve);

}  // namespace prism
