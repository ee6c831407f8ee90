#pragma once
// Lambertian reflection f = R/π, two-sided (wi is drawn on wo's side), sampled with the
// cosine-weighted hemisphere so f·cos/pdf = R exactly.
#include <numbers>
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/sampling/warps.h"

namespace prism::bsdf {

template <int N>
struct Lambertian {
  color::SampledSpectrum<N> reflectance{0.5f};

  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi) const {
    if (!same_hemisphere(wo, wi)) return {};
    return reflectance * std::numbers::inv_pi_v<float>;
  }
  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    return same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(abs_cos_theta(wi)) : 0.0f;
  }
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float /*u_lobe*/, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    Vec3f wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.0f) wi = flip_z(wi);
    const float p = pdf(wo, wi);
    if (p == 0.0f) return std::nullopt;
    BsdfSample<N> s;
    s.wi = wi;
    s.f = eval(wo, wi);
    s.pdf = p;
    return s;
  }
};

}  // namespace prism::bsdf
