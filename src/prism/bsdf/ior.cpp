#include "prism/bsdf/ior.h"

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
  return a + b_um2 / (um * um);
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
