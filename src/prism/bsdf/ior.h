#pragma once
// Spectral indices of refraction: measured complex IORs of metals (embedded tables from
// data/ior/, see data/SOURCES.md) and dispersion models for glass.
#include <string_view>

#include "prism/color/sampled_spectrum.h"
#include "prism/color/spectrum.h"

namespace prism::bsdf {

// η(λ) and k(λ) of a metal, piecewise linear in wavelength (nm) between measured points.
struct ConductorIor {
  color::PiecewiseLinearSpectrum eta;
  color::PiecewiseLinearSpectrum k;
};

// "Au", "Ag", "Cu" (Johnson & Christy 1972) or "Al" (McPeak et al. 2015: measured every
// 5 nm across the visible, where Rakić 1995 has 13 points, so linear interpolation stays
// faithful). Case-sensitive; anything else throws prism::UsageError.
ConductorIor conductor_ior(std::string_view name);

// Cauchy's equation n(λ) = A + B/λ², λ in µm (B in µm²).
struct CauchyIor {
  double a = 1.5;
  double b_um2 = 0.0;
  double operator()(double wavelength_nm) const;
};

// Sellmeier's equation n²(λ) = 1 + Σᵢ Bᵢ λ² / (λ² − Cᵢ), λ in µm (Cᵢ in µm²).
struct SellmeierIor {
  double b[3] = {0.0, 0.0, 0.0};
  double c_um2[3] = {0.0, 0.0, 0.0};
  double operator()(double wavelength_nm) const;
};

// SCHOTT N-BK7 (data/ior/glass_sellmeier_coefficients.csv): n_d(587.56 nm) = 1.5168.
SellmeierIor sellmeier_bk7();

// η of a dielectric at the sampled wavelengths, relative to an outside medium of index
// `outside_ior` (1 for air/vacuum).
template <int N, typename IorModel>
color::SampledSpectrum<N> relative_ior(const IorModel& ior, const color::SampledWavelengths<N>& w,
                                       double outside_ior = 1.0) {
  color::SampledSpectrum<N> eta;
  for (int i = 0; i < N; ++i) eta[i] = static_cast<float>(ior(w.wavelength_nm[i]) / outside_ior);
  return eta;
}

}  // namespace prism::bsdf
