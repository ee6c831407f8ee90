#pragma once
// Rough conductor: the Cook–Torrance microfacet BRDF (Walter et al. 2007, eq. 20)
//   f = D(h) G2(wo, wi) F(wo·h) / (4 |cos θo| |cos θi|),  h = normalize(wo + wi),
// with the height-correlated G2 (Heitz 2014, eq. 99), sampled through the distribution's
// normal sampling (VNDF for GGX) and p(wi) = p(h) / (4 |wo·h|). Two-sided. At α below
// MicrofacetDistribution::kSmoothAlpha it becomes a Fresnel-weighted mirror (delta lobe).
// This BRDF is single scattering: it loses the energy of light that would bounce more than
// once between microfacets (Heitz et al. 2016), more as α grows.
#include <cstdint>
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/fresnel.h"
#include "prism/bsdf/microfacet.h"

namespace prism::bsdf {

// Fresnel term of a conductor: Schlick from F0 (e.g. glTF base colour; F0 = 1 gives a
// lossless mirror for furnace tests), or the exact formula from a complex IOR η + ik
// (see ior.h for measured metals).
template <int N>
struct ConductorFresnel {
  enum class Kind : std::uint8_t { schlick, complex_ior } kind = Kind::schlick;
  color::SampledSpectrum<N> f0_or_eta{1.0f};
  color::SampledSpectrum<N> k{0.0f};

  static ConductorFresnel schlick(const color::SampledSpectrum<N>& f0) { return {Kind::schlick, f0, {}}; }
  static ConductorFresnel complex_ior(const color::SampledSpectrum<N>& eta,
                                      const color::SampledSpectrum<N>& k) {
    return {Kind::complex_ior, eta, k};
  }
  color::SampledSpectrum<N> operator()(float cos_theta) const {
    return kind == Kind::schlick ? fresnel_schlick(f0_or_eta, cos_theta)
                                 : fresnel_conductor(cos_theta, f0_or_eta, k);
  }
};

template <int N>
struct RoughConductor {
  MicrofacetDistribution distribution;
  ConductorFresnel<N> fresnel;

  bool is_specular() const { return distribution.effectively_smooth(); }

  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi) const {
    if (is_specular()) return {};
    const auto r = upper_reflection(wo, wi);
    if (!r) return {};
    const float scale = distribution.D(r->h) * distribution.G2(r->o, r->i) / (4.0f * r->o.z * r->i.z);
    return fresnel(dot(r->o, r->h)) * scale;
  }

  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (is_specular()) return 0.0f;
    const auto r = upper_reflection(wo, wi);
    return r ? distribution.pdf_microfacet_normal(r->o, r->h) * reflection_jacobian(r->o, r->h) : 0.0f;
  }

  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float /*u_lobe*/, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    BsdfSample<N> s;
    if (is_specular()) {
      s.wi = Vec3f(-wo.x, -wo.y, wo.z);
      s.f = fresnel(abs_cos_theta(wo)) * (1.0f / abs_cos_theta(s.wi));
      s.pdf = 1.0f;
      s.is_specular = true;
      return s;
    }
    const Vec3f o = wo.z < 0.0f ? flip_z(wo) : wo;
    const Vec3f h = distribution.sample_microfacet_normal(o, u);
    const Vec3f i = reflect(o, h);
    if (i.z <= 0.0f) return std::nullopt;  // reflected below the surface: no valid path
    s.wi = wo.z < 0.0f ? flip_z(i) : i;
    s.pdf = pdf(wo, s.wi);
    if (s.pdf == 0.0f) return std::nullopt;
    s.f = eval(wo, s.wi);
    return s;
  }
};

}  // namespace prism::bsdf
