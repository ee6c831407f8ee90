#pragma once
// The Jakob & Hanika 2019 spectrum model ("A Low-Dimensional Function Space for Efficient
// Spectral Upsampling", Computer Graphics Forum 38(2)): s(λ) = S(c₀λ² + c₁λ + c₂) with the
// sigmoid S(x) = ½ + x / (2√(1 + x²)) (paper eq. 3), λ in nm. Smooth, bounded to [0, 1],
// and three numbers per colour.
#include <cmath>

namespace prism::color {

inline double sigmoid_jakob_hanika(double x) {
  if (std::isinf(x)) return x > 0 ? 1.0 : 0.0;
  return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
}

struct SigmoidPolynomial {
  double c0 = 0.0, c1 = 0.0, c2 = 0.0;  // coefficients of λ², λ, 1 with λ in nm

  double operator()(double wavelength_nm) const {
    return sigmoid_jakob_hanika(std::fma(std::fma(c0, wavelength_nm, c1), wavelength_nm, c2));
  }
  // The constant spectrum v ∈ [0, 1] (v = 0 and 1 need infinite c₂): S⁻¹(v).
  static SigmoidPolynomial constant(double v) {
    if (v <= 0.0) return {0.0, 0.0, -INFINITY};
    if (v >= 1.0) return {0.0, 0.0, INFINITY};
    return {0.0, 0.0, (v - 0.5) / std::sqrt(v * (1.0 - v))};
  }
};

}  // namespace prism::color
