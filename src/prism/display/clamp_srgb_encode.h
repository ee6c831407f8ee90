#pragma once
// The foundation's display transform: clamp linear Rec.709 to [0, 1] and apply the sRGB
// OETF. It stands in until the ACES display pipeline replaces it as the default.
#include "prism/io/image.h"

namespace prism {

// bit_depth 8 or 16; quantisation rounds to nearest.
EncodedImage clamp_srgb_encode(const ImageRgbF& linear_rec709, int bit_depth = 8);

}  // namespace prism
