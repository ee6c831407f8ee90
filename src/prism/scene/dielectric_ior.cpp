#include "prism/scene/dielectric_ior.h"

#include <limits>

namespace prism {

double dielectric_ior(const Material& m, double wavelength_nm) {
  const auto& c = m.dispersion_coefficients;
  switch (m.dispersion) {
    case DispersionModel::cauchy: return bsdf::CauchyIor{c[0], c[1]}(wavelength_nm);
    case DispersionModel::sellmeier: {
      bsdf::SellmeierIor s;
      for (int i = 0; i < 3; ++i) {
        s.b[i] = c[static_cast<std::size_t>(i)];
        s.c_um2[i] = c[static_cast<std::size_t>(i + 3)];
      }
      return s(wavelength_nm);
    }
    case DispersionModel::none: break;
  }
  return m.ior;
}

void set_cauchy_dispersion(Material& m, const bsdf::CauchyIor& glass) {
  m.dispersion = DispersionModel::cauchy;
  m.dispersion_coefficients = {static_cast<float>(glass.a), static_cast<float>(glass.b_um2), 0, 0, 0, 0};
}

double dielectric_abbe_number(const Material& m) {
  if (m.dispersion == DispersionModel::none) return std::numeric_limits<double>::infinity();
  return bsdf::abbe_number([&m](double nm) { return dielectric_ior(m, nm); });
}

}  // namespace prism
