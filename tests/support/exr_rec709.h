#pragma once
// The Rec. 709 / sRGB primaries and D65 white (ITU-R BT.709-6, table item 1.3-1.4) as an
// OpenEXR chromaticities attribute, for the EXR reading and writing tests. Declared once so
// that those files can share a translation unit (unity builds).
#include "prism/io/exr.h"

namespace prism::test {

inline constexpr ExrChromaticities kRec709{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};

}  // namespace prism::test
