#pragma once
// Perfect mirror with a constant reflectance tint (no Fresnel): the delta lobe
// f = R δ(wi − mirror(wo)) / |cos θi|, sampled with probability 1. Two-sided.
#include <optional>

#include "prism/bsdf/bsdf_sample.h"

namespace prism::bsdf {

template <int N>
struct SpecularReflection {
  color::SampledSpectrum<N> reflectance{1.0f};

  color::SampledSpectrum<N> eval(const Vec3f&, const Vec3f&) const { return {}; }
  float pdf(const Vec3f&, const Vec3f&) const { return 0.0f; }
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float /*u_lobe*/, Vec2f /*u*/) const {
    if (wo.z == 0.0f) return std::nullopt;
    BsdfSample<N> s;
    s.wi = Vec3f(-wo.x, -wo.y, wo.z);
    s.f = reflectance * (1.0f / abs_cos_theta(s.wi));
    s.pdf = 1.0f;
    s.is_specular = true;
    return s;
  }
};

}  // namespace prism::bsdf
