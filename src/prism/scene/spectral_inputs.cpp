#include "prism/scene/spectral_inputs.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"

namespace prism {
namespace {

// The dense table's points over the visible range the renderer samples (380–780 nm).
color::PiecewiseLinearSpectrum visible_part(const color::DenseSpectrum& s) {
  std::vector<double> nm, values;
  for (double l = color::kVisibleMinNm; l <= color::kVisibleMaxNm + 1e-9; l += 1.0) {
    nm.push_back(l);
    values.push_back(s(l));
  }
  return color::PiecewiseLinearSpectrum(std::move(nm), std::move(values));
}

}  // namespace

std::optional<color::PiecewiseLinearSpectrum> named_emission_spectrum(std::string_view name) {
  std::string n(name);
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (n == "D65") return visible_part(color::standard_illuminant(color::StandardIlluminant::d65));
  if (n == "D50") return visible_part(color::standard_illuminant(color::StandardIlluminant::d50));
  if (n == "A") return visible_part(color::standard_illuminant(color::StandardIlluminant::a));
  if (n == "E") return visible_part(color::standard_illuminant(color::StandardIlluminant::e));
  std::string_view digits(n);
  if (digits.starts_with("FL"))
    digits.remove_prefix(2);
  else if (digits.starts_with("F"))
    digits.remove_prefix(1);
  else
    return std::nullopt;
  if (digits.empty() || digits.size() > 2 || !std::all_of(digits.begin(), digits.end(), ::isdigit) ||
      digits.front() == '0')
    return std::nullopt;
  const int number = std::stoi(std::string(digits));
  if (number < 1 || number > 12) return std::nullopt;
  return visible_part(color::fluorescent_illuminant(number));
}

color::PiecewiseLinearSpectrum blackbody_emission_spectrum(double temperature_k) {
  const color::BlackbodySpectrum planck(temperature_k, /*normalized=*/true);
  std::vector<double> nm, values;
  for (int l = 360; l <= 830; ++l) {
    nm.push_back(l);
    values.push_back(planck(l));
  }
  return color::PiecewiseLinearSpectrum(std::move(nm), std::move(values));
}

Vec3f emission_spectrum_srgb(const color::PiecewiseLinearSpectrum& spd) {
  const Vec3d rgb = max(color::color_space("srgb").xyz_to_rgb * color::spectrum_to_xyz(spd), Vec3d(0.0));
  const double m = std::max({rgb.x, rgb.y, rgb.z});
  return m > 0.0 ? Vec3f(rgb / m) : Vec3f(0.0f);
}

Vec3f reflectance_spectrum_srgb(const color::PiecewiseLinearSpectrum& reflectance) {
  const Vec3d xyz = color::reflectance_to_xyz(reflectance, color::standard_illuminant(color::StandardIlluminant::e));
  const Vec3d rgb = color::spectral_xyz_to_rgb_matrix(color::color_space("srgb")) * xyz;
  return Vec3f(min(max(rgb, Vec3d(0.0)), Vec3d(1.0)));
}

}  // namespace prism
