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

const char* picker_space_name(ColorPickerSpace space) {
  switch (space) {
    case ColorPickerSpace::acescg: return "acescg";
    case ColorPickerSpace::rec2020: return "rec2020";
    case ColorPickerSpace::srgb: break;
  }
  return "srgb";
}

Vec3d picker_color_in_rec709(const Vec3f& color, ColorPickerSpace space) {
  if (space == ColorPickerSpace::srgb) return Vec3d(color);
  static const std::array<Mat3, 3> to_rec709 = [] {
    std::array<Mat3, 3> m;
    for (const ColorPickerSpace s : {ColorPickerSpace::srgb, ColorPickerSpace::acescg, ColorPickerSpace::rec2020})
      m[static_cast<std::size_t>(s)] = color::conversion_matrix(picker_color_space(s), color::color_space("srgb"));
    return m;
  }();
  return to_rec709[static_cast<std::size_t>(space)] * Vec3d(color);
}

const Mat3& rec709_to_picker_space(ColorPickerSpace space) {
  static const std::array<Mat3, 3> matrices = [] {
    std::array<Mat3, 3> m;
    for (const ColorPickerSpace s : {ColorPickerSpace::srgb, ColorPickerSpace::acescg, ColorPickerSpace::rec2020})
      m[static_cast<std::size_t>(s)] = color::conversion_matrix(color::color_space("srgb"), picker_color_space(s));
    return m;
  }();
  return matrices[static_cast<std::size_t>(space)];
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

Mat3 textured_emission_matrix(const Emission& e, const color::ColorSpace& target) {
  const double y = relative_luminance(e.color, e.color_space);
  if (!(y > 0.0) || !(e.luminance_nits > 0.0f)) return Mat3::diagonal(Vec3d(0.0));
  const Mat3 to_target = color::conversion_matrix(picker_color_space(e.color_space), target);
  return to_target * Mat3::diagonal(Vec3d(e.color) * (static_cast<double>(e.luminance_nits) / y));
}

}  // namespace prism
