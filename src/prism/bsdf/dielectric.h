#pragma once
// Dielectric interface, smooth (delta reflection + refraction) or rough (GGX/Beckmann/
// Blinn-Phong microfacets: Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces"), with a constant or per-wavelength relative IOR.
//
// Convention: eta[c] = η_inside / η_outside for channel c, "outside" being the side the
// shading normal (local +z) points to. Either direction may be on either side.
//
// Radiance vs importance (TransportMode): for refraction the radiance form carries
// 1/η_rel² with η_rel = η_i/η_o (the IOR of wi's medium over wo's), i.e. radiance grows by
// (η_o/η_i)² entering a denser medium (L/η² is invariant); the importance form does not
// (Veach 1997 §5.2). The radiance BTDF then obeys f(wo, wi)/η_o² = f(wi, wo)/η_i².
// Camera paths use TransportMode::radiance (default).
//
// Dispersion (the channels' η differ; is_dispersive()): the refracted direction depends
// on wavelength, so one sampled direction serves one wavelength only. The rules:
//  - sample() draws wi with channel 0's η and returns f, pdf for channel 0; the other
//    channels of f are 0 and `dispersive` is set, for reflection too (the lobe choice
//    used channel 0's Fresnel term).
//  - eval() returns every channel with its own η (physically correct per wavelength);
//    pdf() is channel 0's density.
//  - The integrator must therefore, at any vertex whose BSDF is_dispersive(), terminate
//    the secondary wavelengths BEFORE next-event estimation and sampling (hero wavelength
//    rendering, Wilkie et al. 2014): their pdf set to 0 so they contribute nothing from
//    here on, and channel 0's contribution re-weighted to stand for all N (pbrt-v4's
//    TerminateSecondary divides pdf[0] by N). With all estimates on channel 0, NEE, MIS
//    and BSDF sampling use one consistent η and stay unbiased.
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/fresnel.h"
#include "prism/bsdf/microfacet.h"

namespace prism::bsdf {

namespace detail {

// The scalar rough-dielectric BSDF for one relative IOR (Walter et al. 2007, eqs. 20–21,
// with the generalised half vector of eq. 16). Returns f (no cosine) and, through
// pdf_out, the density with which sample() produces wi (reflection chosen with
// probability F, as sample() does).
float rough_dielectric_f_pdf(const MicrofacetDistribution& dist, const Vec3f& wo,
                             const Vec3f& wi, float eta, TransportMode mode, float* pdf_out);

}  // namespace detail

template <int N>
struct Dielectric {
  color::SampledSpectrum<N> eta{1.5f};
  MicrofacetDistribution distribution = MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.0f);
  // Multiplies transmitted light at each crossing, in [0, 1] per channel; reflection is
  // untinted (glTF KHR_materials_transmission: the BTDF is weighted by the base colour).
  color::SampledSpectrum<N> transmission_tint{1.0f};

  // An index-matched interface (η = 1) does not scatter, however rough: light passes it
  // unbent, as through a smooth one (pbrt-v4's DielectricBxDF does the same). The rough
  // model cannot say so: its transmission half-vector −(wo + η wi) vanishes at η = 1, and
  // rough glass of ior 1 rendered black.
  bool is_specular() const { return distribution.effectively_smooth() || (eta[0] == 1.0f && !is_dispersive()); }
  bool is_dispersive() const {
    for (int c = 1; c < N; ++c)
      if (eta[c] != eta[0]) return true;
    return false;
  }

  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi,
                                 TransportMode mode = TransportMode::radiance) const {
    if (is_specular()) return {};
    color::SampledSpectrum<N> f;
    if (!is_dispersive()) {
      f = color::SampledSpectrum<N>(detail::rough_dielectric_f_pdf(distribution, wo, wi, eta[0], mode, nullptr));
    } else {
      for (int c = 0; c < N; ++c) f[c] = detail::rough_dielectric_f_pdf(distribution, wo, wi, eta[c], mode, nullptr);
    }
    return wo.z * wi.z < 0.0f ? f * transmission_tint : f;
  }

  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (is_specular()) return 0.0f;
    float p = 0.0f;
    detail::rough_dielectric_f_pdf(distribution, wo, wi, eta[0], TransportMode::radiance, &p);
    return p;
  }

  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f u,
                                      TransportMode mode = TransportMode::radiance) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float eta0 = eta[0];
    Vec3f h(0.0f, 0.0f, 1.0f);
    if (!is_specular()) h = distribution.sample_microfacet_normal(wo, u);
    // Choose reflection with probability F, refraction with 1 − F (F = 1 under TIR).
    const float F = fresnel_dielectric(dot(wo, h), eta0);
    BsdfSample<N> s;
    s.dispersive = is_dispersive();
    if (u_lobe < F) {
      s.wi = reflect(wo, h);
      if (!same_hemisphere(wo, s.wi)) return std::nullopt;
    } else {
      if (!refract(wo, h, eta0, s.wi)) return std::nullopt;
      if (s.wi.z * wo.z >= 0.0f) return std::nullopt;
      s.is_transmission = true;
      s.eta = wo.z > 0.0f ? eta0 : 1.0f / eta0;
    }
    if (is_specular()) {
      s.is_specular = true;
      s.pdf = s.is_transmission ? 1.0f - F : F;
      color::SampledSpectrum<N> weight;
      for (int c = 0; c < N; ++c) {
        if (s.dispersive && c > 0) break;
        const float Fc = fresnel_dielectric(wo.z, eta[c]);
        weight[c] = s.is_transmission ? (1.0f - Fc) : Fc;
        if (s.is_transmission && mode == TransportMode::radiance) weight[c] /= s.eta * s.eta;
      }
      s.f = weight * (1.0f / abs_cos_theta(s.wi));
      if (s.is_transmission) s.f = s.f * transmission_tint;
      return s.pdf > 0.0f ? std::optional(s) : std::nullopt;
    }
    const float f0 = detail::rough_dielectric_f_pdf(distribution, wo, s.wi, eta0, mode, &s.pdf);
    if (s.pdf == 0.0f || f0 == 0.0f) return std::nullopt;
    if (s.dispersive) s.f[0] = f0;
    else s.f = color::SampledSpectrum<N>(f0);
    if (s.is_transmission) s.f = s.f * transmission_tint;
    return s;
  }
};

}  // namespace prism::bsdf
