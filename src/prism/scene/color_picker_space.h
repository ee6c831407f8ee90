#pragma once
// The colour-picker spaces a scene's colours are given in: linear Rec.709 (sRGB
// primaries), ACEScg (AP1) or Rec.2020. A light colour, a base colour and a colour
// texture's texels each say which (so a pure ACEScg blue, or a Rec.2020 green no Rec.709
// reflectance reaches, is expressible). scene/emission.h converts between them.
#include <cstdint>

namespace prism {

enum class ColorPickerSpace : std::uint8_t { srgb, acescg, rec2020 };

}  // namespace prism
