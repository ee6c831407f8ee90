#pragma once
// Analytic multi-lobe fit to the CIE 1931 2° colour-matching functions: Wyman, Sloan &
// Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
// JCGT 2(2), eq. 4 — each CMF is a sum of piecewise Gaussians whose width differs left
// and right of the mean. Cheap and table-free, hence the seed renderer's GPU choice; its
// error against the table is measured by Cie1931Wyman.MultiLobeFitErrorAgainstTheTable in
// tests/color/cie_1931_test.cpp.
#include <cmath>

#include "prism/core/vec.h"

namespace prism::color {

namespace detail {
// The paper's piecewise Gaussian g(λ; μ, σ₁, σ₂) = exp(−½ ((λ−μ)/σ)²), σ = σ₁ for λ < μ
// and σ₂ otherwise.
inline double wyman_lobe(double wavelength_nm, double mean_nm, double sigma_below_nm,
                         double sigma_above_nm) {
  const double t = (wavelength_nm - mean_nm) /
                   (wavelength_nm < mean_nm ? sigma_below_nm : sigma_above_nm);
  return std::exp(-0.5 * t * t);
}
}  // namespace detail

// x̄, ȳ, z̄ from JCGT 2(2) eq. 4 (coefficients as printed in the paper).
inline Vec3d cie1931_xyz_bar_wyman(double wavelength_nm) {
  using detail::wyman_lobe;
  const double l = wavelength_nm;
  const double x = 1.056 * wyman_lobe(l, 599.8, 37.9, 31.0) + 0.362 * wyman_lobe(l, 442.0, 16.0, 26.7) -
                   0.065 * wyman_lobe(l, 501.1, 20.4, 26.2);
  const double y = 0.821 * wyman_lobe(l, 568.8, 46.9, 40.5) + 0.286 * wyman_lobe(l, 530.9, 16.3, 31.1);
  const double z = 1.217 * wyman_lobe(l, 437.0, 11.8, 36.0) + 0.681 * wyman_lobe(l, 459.0, 26.0, 13.8);
  return {x, y, z};
}

}  // namespace prism::color
