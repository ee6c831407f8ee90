#pragma once
// Radiance of an emitter in an RGB space: the colour is converted from its picker space
// (with Bradford adaptation between whites) and scaled so that the radiance's luminance
// equals the requested nits.
#include <functional>
#include <optional>

#include "prism/color/color_space.h"
#include "prism/scene/material.h"

namespace prism {

const color::ColorSpace& picker_color_space(ColorPickerSpace space);
// Its name as the scene formats write it: "srgb", "acescg" or "rec2020".
const char* picker_space_name(ColorPickerSpace space);
// Its name in messages: "Rec.709", "ACEScg" or "Rec.2020".
const char* picker_space_label(ColorPickerSpace space);

// A linear colour given in `space` with Rec.709 primaries (Bradford between whites, so
// white stays white). Components are negative where the colour lies outside Rec.709.
Vec3d picker_color_in_rec709(const Vec3f& color, ColorPickerSpace space);
// The first of Rec.709, Rec.2020 and ACEScg whose gamut holds `space`'s primaries (its pure
// red, green and blue, converted with Bradford between whites, none outside the gamut by
// more than round-off, color::is_outside_gamut); ACEScg, the widest, where none does
// (ACES2065-1's AP0 primaries lie outside every real gamut).
ColorPickerSpace smallest_picker_space_holding(const color::ColorSpace& space);
// The same for RGB whose conversion into a candidate space `to_candidate` gives (an image's
// ICC colorants, which are no set of chromaticities; scene/image_color_tags.h).
ColorPickerSpace smallest_picker_space_holding(const std::function<Mat3(const color::ColorSpace&)>& to_candidate);
// The matrix taking linear RGB in `from` to `to` (Bradford between whites; the identity
// where they are the same): a texel's colour in a wide-gamut material's space.
const Mat3& picker_space_conversion(ColorPickerSpace from, ColorPickerSpace to);
// The same where it lies within Rec.709 (components below 1e-5 of the largest, float
// round-off of the conversion, are clipped to 0); nothing where it lies outside.
std::optional<Vec3f> picker_color_within_rec709(const Vec3f& color, ColorPickerSpace space);

// Linear RGB radiance in `target` whose CIE Y equals luminance_nits. Zero for black.
Vec3d emission_radiance_rgb(const Vec3f& color, ColorPickerSpace space, float luminance_nits,
                            const color::ColorSpace& target);
inline Vec3d emission_radiance_rgb(const Emission& e, const color::ColorSpace& target) {
  return emission_radiance_rgb(e.color, e.color_space, e.luminance_nits, target);
}

// For an emitter with an emission texture: the matrix taking a linear texel in
// `texel_space` (converted to the picker space, where it multiplies the colour channel by
// channel, as a base colour texture's texels do) to radiance in `target`,
// M · diag(colour) · L / Y(colour) · C. A white texel gives emission_radiance_rgb(e, target).
Mat3 textured_emission_matrix(const Emission& e, const color::ColorSpace& target,
                              ColorPickerSpace texel_space = ColorPickerSpace::srgb);

// Luminance (CIE Y) of a linear RGB colour in the given picker space.
double relative_luminance(const Vec3f& color, ColorPickerSpace space);

}  // namespace prism
