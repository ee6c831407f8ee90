#include "prism/scene/emission.h"

#include <array>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"

namespace prism {

const color::ColorSpace& picker_color_space(ColorPickerSpace space) {
  switch (space) {
    case ColorPickerSpace::acescg: return color::color_space("acescg");
    case ColorPickerSpace::rec2020: return color::color_space("rec2020");
    case ColorPickerSpace::srgb: break;
  }
  return color::color_space("srgb");
}

const char* picker_space_name(ColorPickerSpace space) { return picker_color_space(space).name.c_str(); }

const char* picker_space_label(ColorPickerSpace space) {
  switch (space) {
    case ColorPickerSpace::acescg: return "ACEScg";
    case ColorPickerSpace::rec2020: return "Rec.2020";
    case ColorPickerSpace::srgb: break;
  }
  return "Rec.709";
}

Vec3d picker_color_in_rec709(const Vec3f& color, ColorPickerSpace space) {
  if (space == ColorPickerSpace::srgb) return Vec3d(color);
  return picker_space_conversion(space, ColorPickerSpace::srgb) * Vec3d(color);
}

const Mat3& picker_space_conversion(ColorPickerSpace from, ColorPickerSpace to) {
  constexpr ColorPickerSpace kSpaces[] = {ColorPickerSpace::srgb, ColorPickerSpace::acescg, ColorPickerSpace::rec2020};
  static const std::array<std::array<Mat3, 3>, 3> matrices = [&] {
    std::array<std::array<Mat3, 3>, 3> m;
    for (const ColorPickerSpace f : kSpaces)
      for (const ColorPickerSpace t : kSpaces)
        m[static_cast<std::size_t>(f)][static_cast<std::size_t>(t)] =
            f == t ? Mat3::identity() : color::conversion_matrix(picker_color_space(f), picker_color_space(t));
    return m;
  }();
  return matrices[static_cast<std::size_t>(from)][static_cast<std::size_t>(to)];
}

ColorPickerSpace smallest_picker_space_holding(const color::ColorSpace& space) {
  return smallest_picker_space_holding(
      [&](const color::ColorSpace& candidate) { return color::conversion_matrix(space, candidate); });
}

ColorPickerSpace smallest_picker_space_holding(const std::function<Mat3(const color::ColorSpace&)>& to_candidate) {
  for (const ColorPickerSpace candidate : {ColorPickerSpace::srgb, ColorPickerSpace::rec2020}) {
    const Mat3 to = to_candidate(picker_color_space(candidate));
    bool holds = true;
    for (const Vec3d primary : {Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)})
      holds = holds && !color::is_outside_gamut(to * primary);
    if (holds) return candidate;
  }
  return ColorPickerSpace::acescg;
}

std::optional<Vec3f> picker_color_within_rec709(const Vec3f& color, ColorPickerSpace space) {
  const Vec3d srgb = picker_color_in_rec709(color, space);
  if (color::is_outside_gamut(srgb)) return std::nullopt;
  return Vec3f(max(srgb, Vec3d(0.0)));
}

double relative_luminance(const Vec3f& color, ColorPickerSpace space) {
  return (picker_color_space(space).rgb_to_xyz * Vec3d(color)).y;
}

Vec3d emission_radiance_rgb(const Vec3f& color, ColorPickerSpace space, float luminance_nits,
                            const color::ColorSpace& target) {
  const double y = relative_luminance(color, space);
  if (!(y > 0.0) || !(luminance_nits > 0.0f)) return Vec3d(0.0);
  const Mat3 to_target = color::conversion_matrix(picker_color_space(space), target);
  return to_target * Vec3d(color) * (static_cast<double>(luminance_nits) / y);
}

Mat3 textured_emission_matrix(const Emission& e, const color::ColorSpace& target, ColorPickerSpace texel_space) {
  const double y = relative_luminance(e.color, e.color_space);
  if (!(y > 0.0) || !(e.luminance_nits > 0.0f)) return Mat3::diagonal(Vec3d(0.0));
  const Mat3 to_target = color::conversion_matrix(picker_color_space(e.color_space), target);
  const Mat3 m = to_target * Mat3::diagonal(Vec3d(e.color) * (static_cast<double>(e.luminance_nits) / y));
  return texel_space == e.color_space ? m : m * picker_space_conversion(texel_space, e.color_space);
}

}  // namespace prism
