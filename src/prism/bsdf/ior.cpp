#include "prism/bsdf/ior.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "prism/color/tabulated_data.h"
#include "prism/core/error.h"

namespace prism::bsdf {
namespace {

ConductorIor from_table(const color::data::Table& t) {
  std::vector<double> nm(static_cast<std::size_t>(t.rows)), n(nm.size()), k(nm.size());
  for (int r = 0; r < t.rows; ++r) {
    nm[r] = t.at(r, 0);
    n[r] = t.at(r, 1);
    k[r] = t.at(r, 2);
  }
  return {color::PiecewiseLinearSpectrum(nm, std::move(n)), color::PiecewiseLinearSpectrum(nm, std::move(k))};
}

// 1/λ² in µm⁻², λ in nm: the variable in which Cauchy's equation is a line.
double inverse_square_um(double wavelength_nm) {
  const double um = wavelength_nm * 1e-3;
  return 1.0 / (um * um);
}

}  // namespace

ConductorIor conductor_ior(std::string_view name) {
  if (name == "Au") return from_table(color::data::ior_au_johnson());
  if (name == "Ag") return from_table(color::data::ior_ag_johnson());
  if (name == "Cu") return from_table(color::data::ior_cu_johnson());
  if (name == "Al") return from_table(color::data::ior_al_mcpeak());
  throw UsageError("unknown conductor '" + std::string(name) + "' (known: Au, Ag, Cu, Al)");
}

double CauchyIor::operator()(double wavelength_nm) const {
  const double um = wavelength_nm * 1e-3;
  return std::max(a + b_um2 / (um * um), 1.0);
}

CauchyIor CauchyIor::from_abbe_number(double n_d, double abbe_number) {
  const double b = (n_d - 1.0) / (abbe_number * (inverse_square_um(kFraunhoferF_nm) - inverse_square_um(kFraunhoferC_nm)));
  return {n_d - b * inverse_square_um(kFraunhoferD_nm), b};
}

CauchyFit fit_cauchy(std::span<const double> wavelength_nm, std::span<const double> n) {
  const double count = static_cast<double>(n.size());
  double mean_x = 0.0, mean_n = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    mean_x += inverse_square_um(wavelength_nm[i]) / count;
    mean_n += n[i] / count;
  }
  double sxx = 0.0, sxn = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double dx = inverse_square_um(wavelength_nm[i]) - mean_x;
    sxx += dx * dx;
    sxn += dx * (n[i] - mean_n);
  }
  const double b = sxx > 0.0 ? sxn / sxx : 0.0;
  CauchyFit fit{{mean_n - b * mean_x, b}, 0.0};
  for (std::size_t i = 0; i < n.size(); ++i)
    fit.max_residual = std::max(fit.max_residual, std::abs(n[i] - (fit.ior.a + b * inverse_square_um(wavelength_nm[i]))));
  return fit;
}

double SellmeierIor::operator()(double wavelength_nm) const {
  const double um2 = wavelength_nm * wavelength_nm * 1e-6;
  double n2 = 1.0;
  for (int i = 0; i < 3; ++i) n2 += b[i] * um2 / (um2 - c_um2[i]);
  return std::sqrt(n2);
}

SellmeierIor sellmeier_bk7() {
  const color::data::Table t = color::data::sellmeier_nbk7();
  SellmeierIor s;
  for (int i = 0; i < 3; ++i) {
    s.b[i] = t.at(0, 2 * i);
    s.c_um2[i] = t.at(0, 2 * i + 1);
  }
  return s;
}

}  // namespace prism::bsdf
