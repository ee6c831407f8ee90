#include "prism/bsdf/fresnel.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace prism::bsdf {

float fresnel_schlick(float f0, float cos_theta) {
  const float m = std::clamp(1.0f - std::abs(cos_theta), 0.0f, 1.0f);
  const float m2 = m * m;
  return f0 + (1.0f - f0) * m2 * m2 * m;
}

float refracted_cos_theta(float cos_theta_i, float eta) {
  if (cos_theta_i < 0.0f) {
    eta = 1.0f / eta;
    cos_theta_i = -cos_theta_i;
  }
  // Snell: sin θt = sin θi / η.
  const float sin2_t = std::max(0.0f, 1.0f - cos_theta_i * cos_theta_i) / (eta * eta);
  if (sin2_t >= 1.0f) return -1.0f;
  return std::sqrt(1.0f - sin2_t);
}

float fresnel_dielectric(float cos_theta_i, float eta) {
  cos_theta_i = std::clamp(cos_theta_i, -1.0f, 1.0f);
  const float cos_t = refracted_cos_theta(cos_theta_i, eta);
  if (cos_t < 0.0f) return 1.0f;  // total internal reflection
  if (cos_theta_i < 0.0f) {
    eta = 1.0f / eta;
    cos_theta_i = -cos_theta_i;
  }
  // Amplitude coefficients for p and s polarisation (Born & Wolf §1.5.2).
  const float r_parallel = (eta * cos_theta_i - cos_t) / (eta * cos_theta_i + cos_t);
  const float r_perpendicular = (cos_theta_i - eta * cos_t) / (cos_theta_i + eta * cos_t);
  return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

float fresnel_conductor(float cos_theta_i, float eta, float k) {
  using complex = std::complex<float>;
  const float cos_i = std::clamp(std::abs(cos_theta_i), 0.0f, 1.0f);
  const complex n(eta, k);
  // The dielectric formulas with complex η: sin²θt = sin²θi / η², cos θt = sqrt(1 − sin²θt)
  // on the principal branch (Re ≥ 0), which selects the decaying transmitted wave.
  const complex sin2_t = (1.0f - cos_i * cos_i) / (n * n);
  const complex cos_t = std::sqrt(1.0f - sin2_t);
  const complex r_parallel = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  const complex r_perpendicular = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  return 0.5f * (std::norm(r_parallel) + std::norm(r_perpendicular));
}

}  // namespace prism::bsdf
