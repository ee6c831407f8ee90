#pragma once
// A colour texture's texels converted at load from the primaries its file names (an
// OpenEXR's `chromaticities`, a Radiance picture's PRIMARIES or XYZE format) into the
// space its use asks for (TextureContent), with Bradford adaptation between whites. What
// falls outside the target gamut is clipped (a texel there cannot hold it), and counted so
// that the loader can warn.
#include <cstddef>
#include <string>

#include "prism/color/color_space.h"
#include "prism/core/mat3.h"
#include "prism/scene/texture.h"

namespace prism {

// Chromaticities within 1e-4 in x and y are the same primaries: rounding in how a writer
// printed a standard's.
bool same_primaries(const color::Primaries& given, const color::ColorSpace& space);

// "red 0.7080,0.2920 green ... white 0.3127,0.3290", for messages.
std::string primaries_text(const color::Primaries& p);

// The space a colour content puts a file's texels in: for color_own_gamut the smallest of
// Rec.709, Rec.2020 and ACEScg that holds `file_space`, otherwise the one it asks for.
ColorPickerSpace texel_space_for(TextureContent content, const color::ColorSpace& file_space);

// Replaces every RGB texel (halves or floats; channels 3, or 4 with alpha, which stays) v by conversion · v, clipping
// what falls below 0, and sets texel_space to `target`. Returns how many texels were
// clipped.
std::size_t convert_texels(TextureImage& image, const Mat3& conversion, ColorPickerSpace target);

// "; 12 of 64 texels lie outside ACEScg and were clipped to it", or "" for none.
std::string clipped_texels_text(std::size_t clipped, const TextureImage& image);

}  // namespace prism
