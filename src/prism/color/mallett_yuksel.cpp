// The Mallett–Yuksel 2019 basis from the embedded table.
#include "prism/color/mallett_yuksel.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"
#include "prism/color/tabulated_data.h"

namespace prism::color {

const MallettYukselBasis& mallett_yuksel_basis() {
  static const MallettYukselBasis basis = [] {
    const data::Table t = data::mallett_yuksel_2019_basis();
    std::vector<double> r, g, b;
    for (int i = 0; i < t.rows; ++i) {
      const double sum = t.at(i, 1) + t.at(i, 2) + t.at(i, 3);
      r.push_back(t.at(i, 1) / sum);
      g.push_back(t.at(i, 2) / sum);
      b.push_back(t.at(i, 3) / sum);
    }
    const double first_nm = t.at(0, 0), step_nm = t.at(1, 0) - t.at(0, 0);
    return MallettYukselBasis{DenseSpectrum(first_nm, step_nm, std::move(r)),
                              DenseSpectrum(first_nm, step_nm, std::move(g)),
                              DenseSpectrum(first_nm, step_nm, std::move(b))};
  }();
  return basis;
}

Vec3d mallett_yuksel_weights_under_e(Vec3d linear_srgb) {
  static const Mat3 albedo_to_weights = [] {
    const MallettYukselBasis& basis = mallett_yuksel_basis();
    const Mat3 film_to_srgb = spectral_xyz_to_rgb_matrix(color_space("srgb"));
    const DenseSpectrum& e = standard_illuminant(StandardIlluminant::e);
    Mat3 filmed;  // column i: how basis spectrum i films, in linear sRGB
    const DenseSpectrum* spectra[3] = {&basis.r, &basis.g, &basis.b};
    for (int i = 0; i < 3; ++i) {
      const Vec3d rgb = film_to_srgb * reflectance_to_xyz(*spectra[i], e);
      for (int row = 0; row < 3; ++row) filmed(row, i) = rgb[row];
    }
    // Rows scaled so that weights (1, 1, 1), the flat spectrum, film as white: the CMFs'
    // ∫x̄ = ∫ȳ = ∫z̄ holds only to 1e-4 over 380–780 nm, and a white albedo must stay the
    // perfect reflector, s = 1 (furnace tests), as the table's greys are exactly flat.
    for (int row = 0; row < 3; ++row) {
      const double sum = filmed(row, 0) + filmed(row, 1) + filmed(row, 2);
      for (int i = 0; i < 3; ++i) filmed(row, i) /= sum;
    }
    return inverse(filmed);
  }();
  Vec3d clean;
  for (int c = 0; c < 3; ++c) clean[c] = std::isnan(linear_srgb[c]) ? 0.0 : linear_srgb[c];
  return min(max(albedo_to_weights * clean, Vec3d(0.0)), Vec3d(1.0));
}

MallettYukselSpectrum::MallettYukselSpectrum(Vec3d linear_srgb) {
  for (int c = 0; c < 3; ++c) rgb_[c] = std::clamp(std::isnan(linear_srgb[c]) ? 0.0 : linear_srgb[c], 0.0, 1.0);
}

double MallettYukselSpectrum::operator()(double wavelength_nm) const {
  const MallettYukselBasis& basis = mallett_yuksel_basis();
  return rgb_.x * basis.r(wavelength_nm) + rgb_.y * basis.g(wavelength_nm) + rgb_.z * basis.b(wavelength_nm);
}

}  // namespace prism::color
