#pragma once
// Spectral indices of refraction: measured complex IORs of metals (embedded tables from
// data/ior/, see data/SOURCES.md) and dispersion models for glass.
#include <span>
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

// Fraunhofer lines of the Abbe number V_d = (n_d − 1)/(n_F − n_C), in nm: F (hydrogen,
// blue), d (helium, yellow), C (hydrogen, red), to the two decimals of the SCHOTT
// catalogue. KHR_materials_dispersion's closed form n_d + (n_d − 1)/V_d (523655/λ² −
// 1.5168) is built on these (1/(λ_F⁻² − λ_C⁻²) = 523655 nm², that over λ_d² = 1.5168); its
// prose rounds them to 486.1, 587.6 and 656.3.
inline constexpr double kFraunhoferF_nm = 486.13;
inline constexpr double kFraunhoferD_nm = 587.56;
inline constexpr double kFraunhoferC_nm = 656.27;

// Cauchy's equation n(λ) = max(A + B/λ², 1), λ in µm (B in µm²). The floor at 1 is
// KHR_materials_dispersion's: a strong enough dispersion of a low-index glass would
// otherwise put the red end below vacuum's index.
struct CauchyIor {
  double a = 1.5;
  double b_um2 = 0.0;
  double operator()(double wavelength_nm) const;

  // The two-term Cauchy glass with index n_d at the d line and Abbe number V_d: B =
  // (n_d − 1) / (V_d (λ_F⁻² − λ_C⁻²)), A = n_d − B/λ_d² (KHR_materials_dispersion).
  static CauchyIor from_abbe_number(double n_d, double abbe_number);
};

// Sellmeier's equation n²(λ) = 1 + Σᵢ Bᵢ λ² / (λ² − Cᵢ), λ in µm (Cᵢ in µm²).
struct SellmeierIor {
  double b[3] = {0.0, 0.0, 0.0};
  double c_um2[3] = {0.0, 0.0, 0.0};
  double operator()(double wavelength_nm) const;
};

// SCHOTT N-BK7 (data/ior/glass_sellmeier_coefficients.csv): n_d(587.56 nm) = 1.5168.
SellmeierIor sellmeier_bk7();

// The Cauchy glass closest to measured (λ, n) pairs (least squares in n over x = 1/λ², in
// which Cauchy's equation is a line), with the largest |n − n_fit| over the pairs. One
// distinct wavelength gives a constant index. Sizes must match and be ≥ 1.
struct CauchyFit {
  CauchyIor ior;
  double max_residual = 0.0;
};
CauchyFit fit_cauchy(std::span<const double> wavelength_nm, std::span<const double> n);

// V_d = (n_d − 1)/(n_F − n_C) of a dispersion model: exact for a Cauchy glass made by
// CauchyIor::from_abbe_number, the Abbe number of a Sellmeier one; +∞ for a constant n > 1.
template <typename IorModel>
double abbe_number(const IorModel& ior) {
  return (ior(kFraunhoferD_nm) - 1.0) / (ior(kFraunhoferF_nm) - ior(kFraunhoferC_nm));
}

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
