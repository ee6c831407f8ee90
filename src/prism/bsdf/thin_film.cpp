#include "prism/bsdf/thin_film.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism::bsdf {

namespace {

using Complex = std::complex<double>;

// Fresnel amplitude coefficients from medium a into medium b (Born & Wolf §1.5.2, eq. 20,
// in the form with indices and cosines, valid for complex ones).
Complex r_s(Complex eta_a, Complex cos_a, Complex eta_b, Complex cos_b) {
  return (eta_a * cos_a - eta_b * cos_b) / (eta_a * cos_a + eta_b * cos_b);
}
Complex r_p(Complex eta_a, Complex cos_a, Complex eta_b, Complex cos_b) {
  return (eta_b * cos_a - eta_a * cos_b) / (eta_b * cos_a + eta_a * cos_b);
}

}  // namespace

double thin_film_reflectance(double cos_theta, double wavelength_nm, double thickness_nm, double eta_film,
                             double eta_base) {
  if (!(eta_film >= 1.0 && eta_base >= 1.0)) return thin_film_reflectance(cos_theta, wavelength_nm, thickness_nm,
                                                                          eta_film, Complex(eta_base));
  // Real indices of at least air's: every cosine is real (no total reflection from air into
  // denser layers), so are the amplitude coefficients, and
  //   |r|² = (r₀₁² + r₁₂² + 2 r₀₁ r₁₂ cos δ) / (1 + r₀₁² r₁₂² + 2 r₀₁ r₁₂ cos δ)
  // (Born & Wolf §7.6.1, eq. 15): one cosine for both polarisations.
  const double cos0 = std::clamp(cos_theta, 1e-6, 1.0);
  const double sin2_0 = 1.0 - cos0 * cos0;
  const double cos1 = std::sqrt(1.0 - sin2_0 / (eta_film * eta_film));
  const double cos2 = std::sqrt(1.0 - sin2_0 / (eta_base * eta_base));
  const double cos_delta = std::cos(4.0 * std::numbers::pi * thickness_nm * eta_film * cos1 / wavelength_nm);
  const auto airy = [&](double r01, double r12) {
    const double cross = 2.0 * r01 * r12 * cos_delta;
    return (r01 * r01 + r12 * r12 + cross) / (1.0 + r01 * r01 * r12 * r12 + cross);
  };
  const double rs = airy((cos0 - eta_film * cos1) / (cos0 + eta_film * cos1),
                         (eta_film * cos1 - eta_base * cos2) / (eta_film * cos1 + eta_base * cos2));
  const double rp = airy((eta_film * cos0 - cos1) / (eta_film * cos0 + cos1),
                         (eta_base * cos1 - eta_film * cos2) / (eta_base * cos1 + eta_film * cos2));
  return std::clamp(0.5 * (rs + rp), 0.0, 1.0);
}

double thin_film_reflectance(double cos_theta, double wavelength_nm, double thickness_nm, double eta_film,
                             Complex eta_base) {
  const double cos0 = std::clamp(cos_theta, 1e-6, 1.0);
  const double sin2_0 = 1.0 - cos0 * cos0;
  // Snell's law η sin θ = sin θ₀ in every layer; the principal square root gives the
  // propagating (or, past the critical angle, decaying) cosine.
  const Complex eta0(1.0), eta1(eta_film);
  const Complex cos1 = std::sqrt(1.0 - sin2_0 / (eta1 * eta1));
  const Complex cos2 = std::sqrt(1.0 - sin2_0 / (eta_base * eta_base));
  const Complex phase = std::exp(Complex(0.0, 4.0 * std::numbers::pi * thickness_nm / wavelength_nm) * eta1 * cos1);
  const auto airy = [&](Complex r01, Complex r12) {
    const Complex r = (r01 + r12 * phase) / (1.0 + r01 * r12 * phase);
    return std::norm(r);
  };
  const double rs = airy(r_s(eta0, cos0, eta1, cos1), r_s(eta1, cos1, eta_base, cos2));
  const double rp = airy(r_p(eta0, cos0, eta1, cos1), r_p(eta1, cos1, eta_base, cos2));
  return std::clamp(0.5 * (rs + rp), 0.0, 1.0);
}

float eta_from_f0(float f0) {
  const double root = std::sqrt(std::clamp(double(f0), 0.0, 0.99));
  return static_cast<float>((1.0 + root) / (1.0 - root));
}

}  // namespace prism::bsdf
