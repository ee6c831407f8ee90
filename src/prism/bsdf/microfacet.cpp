#include "prism/bsdf/microfacet.h"

#include <algorithm>
#include <limits>
#include <numbers>

namespace prism::bsdf {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// tan²θ of w scaled by the anisotropic roughness: (αx² x² + αy² y²) / z², which is
// α(φ)² tan²θ in Heitz 2014 §5.3 notation.
float alpha_tan2(const Vec3f& w, float ax, float ay) {
  return (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z);
}

// Slope-space form of h (Heitz 2014, eq. 12/13): x̃²/αx² + ỹ²/αy² with slopes −h.xy/h.z.
float scaled_slope2(const Vec3f& h, float ax, float ay) {
  return (h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay)) / (h.z * h.z);
}

// Smith Λ of the Beckmann distribution (Walter et al. 2007, eq. 27 in closed form via erf):
// a = 1 / (α tan θ), Λ = (erf(a) − 1)/2 + exp(−a²) / (2 a √π).
float lambda_beckmann(const Vec3f& w, float ax, float ay) {
  const float at2 = alpha_tan2(w, ax, ay);
  if (at2 <= 0.0f) return 0.0f;
  const float a = 1.0f / std::sqrt(at2);
  return 0.5f * (std::erf(a) - 1.0f) + std::exp(-a * a) / (2.0f * a * std::sqrt(kPi));
}

}  // namespace

float blinn_phong_exponent_from_alpha(float alpha) { return 2.0f / (alpha * alpha) - 2.0f; }
float alpha_from_blinn_phong_exponent(float exponent) { return std::sqrt(2.0f / (exponent + 2.0f)); }

float MicrofacetDistribution::D(const Vec3f& h) const {
  if (h.z <= 0.0f) return 0.0f;
  const float cos2 = h.z * h.z, cos4 = cos2 * cos2;
  switch (type) {
    case MicrofacetType::ggx: {
      // Trowbridge–Reitz (Walter et al. 2007, eq. 33), anisotropic form (Heitz 2014, eq. 85).
      const float e = scaled_slope2(h, alpha_x, alpha_y);
      return 1.0f / (kPi * alpha_x * alpha_y * cos4 * (1.0f + e) * (1.0f + e));
    }
    case MicrofacetType::beckmann: {
      // Walter et al. 2007, eq. 25; anisotropic form Heitz 2014, eq. 84.
      const float e = scaled_slope2(h, alpha_x, alpha_y);
      return std::exp(-e) / (kPi * alpha_x * alpha_y * cos4);
    }
    case MicrofacetType::blinn_phong: {
      // Walter et al. 2007, eq. 30: (e + 2)/(2π) cos^e θh.
      const float e = blinn_phong_exponent_from_alpha(alpha_x);
      return (e + 2.0f) / (2.0f * kPi) * std::pow(h.z, e);
    }
  }
  return 0.0f;
}

float MicrofacetDistribution::lambda(const Vec3f& w) const {
  if (w.z == 0.0f) return std::numeric_limits<float>::infinity();
  switch (type) {
    case MicrofacetType::ggx: {
      // Heitz 2014, eq. 86: Λ = (−1 + sqrt(1 + α² tan² θ)) / 2.
      const float at2 = alpha_tan2(w, alpha_x, alpha_y);
      return 0.5f * (std::sqrt(1.0f + at2) - 1.0f);
    }
    case MicrofacetType::beckmann: return lambda_beckmann(w, alpha_x, alpha_y);
    case MicrofacetType::blinn_phong: return lambda_beckmann(w, alpha_x, alpha_x);
  }
  return 0.0f;
}

float MicrofacetDistribution::G2_transmission(const Vec3f& wo, const Vec3f& wi) const {
  const float a = 1.0f + lambda(wo), b = 1.0f + lambda(wi);
  if (!std::isfinite(a) || !std::isfinite(b)) return 0.0f;
  return std::exp(std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
}

Vec3f MicrofacetDistribution::sample_ndf(Vec2f u) const {
  const float phi = 2.0f * kPi * u.y;
  const float one_minus_u = std::max(1.0f - u.x, 1e-12f);
  if (type == MicrofacetType::blinn_phong) {
    // Walter et al. 2007, eq. 35: cos θh = u^(1/(e+2)).
    const float e = blinn_phong_exponent_from_alpha(alpha_x);
    const float cos_t = std::pow(one_minus_u, 1.0f / (e + 2.0f));
    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
  }
  // D(h)·cos θh dωh is the slope density P22 d²m̃ (Heitz 2014, eq. 12), and both GGX and
  // Beckmann slope densities are the α = 1 density stretched by (αx, αy): sample a unit
  // slope radius by inverting its CDF, then stretch (Walter et al. 2007, eqs. 28, 35).
  const float r = type == MicrofacetType::ggx ? std::sqrt(u.x / one_minus_u)
                                              : std::sqrt(-std::log(one_minus_u));
  const Vec3f h(alpha_x * r * std::cos(phi), alpha_y * r * std::sin(phi), 1.0f);
  return normalize(h);
}

Vec3f MicrofacetDistribution::sample_vndf_heitz2018(const Vec3f& wo, Vec2f u) const {
  const Vec3f w = wo.z < 0.0f ? -wo : wo;
  // Heitz 2018, listing 1: stretch the view to the hemisphere configuration (α = 1),
  // sample the projected area of the hemisphere seen from it, unstretch.
  const Vec3f v = normalize(Vec3f(alpha_x * w.x, alpha_y * w.y, w.z));
  const float len2 = v.x * v.x + v.y * v.y;
  const Vec3f t1 = len2 > 0.0f ? Vec3f(-v.y, v.x, 0.0f) / std::sqrt(len2) : Vec3f(1.0f, 0.0f, 0.0f);
  const Vec3f t2 = cross(v, t1);
  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
  const float p1 = r * std::cos(phi);
  float p2 = r * std::sin(phi);
  // Warp the disk onto the projection of the half-disk facing v (Heitz 2018, §4.2).
  const float s = 0.5f * (1.0f + v.z);
  p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
  const Vec3f n = t1 * p1 + t2 * p2 + v * std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2));
  return normalize(Vec3f(alpha_x * n.x, alpha_y * n.y, std::max(1e-7f, n.z)));
}

Vec3f MicrofacetDistribution::sample_vndf_spherical_cap(const Vec3f& wo, Vec2f u) const {
  const Vec3f w = wo.z < 0.0f ? -wo : wo;
  // Dupuy & Benyoub 2023, §3: in the α = 1 configuration the visible normals are the
  // half vectors between v and a point uniformly distributed on the spherical cap
  // z ∈ [−v.z, 1] of the unit sphere.
  const Vec3f v = normalize(Vec3f(alpha_x * w.x, alpha_y * w.y, w.z));
  const float phi = 2.0f * kPi * u.x;
  const float z = (1.0f - u.y) * (1.0f + v.z) - v.z;
  const float sin_t = std::sqrt(std::clamp(1.0f - z * z, 0.0f, 1.0f));
  const Vec3f c(sin_t * std::cos(phi), sin_t * std::sin(phi), z);
  const Vec3f n = c + v;  // unnormalised half vector; the unstretch normalises
  return normalize(Vec3f(alpha_x * n.x, alpha_y * n.y, std::max(1e-7f, n.z)));
}

float MicrofacetDistribution::pdf_vndf(const Vec3f& wo, const Vec3f& h) const {
  const Vec3f w = wo.z < 0.0f ? -wo : wo;
  if (w.z <= 0.0f) return 0.0f;
  return G1(w) * std::max(0.0f, dot(w, h)) * D(h) / w.z;
}

Vec3f MicrofacetDistribution::sample_microfacet_normal(const Vec3f& wo, Vec2f u) const {
  if (!uses_visible_normals()) return sample_ndf(u);
  return sampling == MicrofacetSampling::spherical_caps ? sample_vndf_spherical_cap(wo, u)
                                                        : sample_vndf_heitz2018(wo, u);
}

float MicrofacetDistribution::pdf_microfacet_normal(const Vec3f& wo, const Vec3f& h) const {
  return uses_visible_normals() ? pdf_vndf(wo, h) : pdf_ndf(h);
}

}  // namespace prism::bsdf
