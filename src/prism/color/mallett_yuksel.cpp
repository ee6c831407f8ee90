// The Mallett–Yuksel 2019 basis from the embedded table.
#include "prism/color/mallett_yuksel.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

MallettYukselSpectrum::MallettYukselSpectrum(Vec3d linear_srgb) {
  for (int c = 0; c < 3; ++c) rgb_[c] = std::clamp(std::isnan(linear_srgb[c]) ? 0.0 : linear_srgb[c], 0.0, 1.0);
}

double MallettYukselSpectrum::operator()(double wavelength_nm) const {
  const MallettYukselBasis& basis = mallett_yuksel_basis();
  return rgb_.x * basis.r(wavelength_nm) + rgb_.y * basis.g(wavelength_nm) + rgb_.z * basis.b(wavelength_nm);
}

}  // namespace prism::color
