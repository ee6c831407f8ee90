#pragma once
// glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, Appendix B):
//   dielectric = fresnel_mix(F0 = 0.04, base = Lambert(base colour), layer = specular)
//   metal      = conductor_fresnel(F0 = base colour, specular)
//   f          = mix(dielectric, metal, metallic)
// which, Schlick being linear in F0, is
//   f = (1 − m)(1 − F_0.04(wi·h)) c/π + F_F0(wi·h) D G2 / (4 |cos θo| |cos θi|),
//   F0 = mix(0.04, c, m),
// with the microfacet lobe GGX at α = roughness² (done by the caller; α is clamped to
// kMinAlpha so that roughness 0 stays a finite, evaluable lobe rather than a delta).
//
// KHR_materials_ior and KHR_materials_specular generalise the dielectric part: its F0 is
// the colour min(((η − 1)/(η + 1))² × specular colour, 1) (0.04 at η = 1.5, white), and its
// specular layer has a weight s (specularFactor) that scales the whole Fresnel term, f90
// included. The extension's fresnel_mix weights the base by 1 − s max(F_F0d), the largest
// RGB component, so that a coloured F0 dims the diffuse part evenly:
//   f = (1 − m)(1 − s F_max F0d(wi·h)) c/π
//       + [(1 − m) s F_F0d(wi·h) + m F_c(wi·h)] D G2 / (4 |cos θo| |cos θi|).
// F0d is per channel (upsampled from its RGB colour in spectral transport); max F0d is that
// RGB colour's, so spectral and RGB renders dim the base alike. With s = 1 the bracket is
// F of mix(F0d, c, m) (Schlick is affine in F0), the form above.
//
// KHR_materials_iridescence puts a thin film of weight w on both bases (bsdf/thin_film.h):
// the metal's Fresnel becomes (1 − w) F_c + w R_film(metal), the dielectric layer's
// (1 − w) s F_F0d + w R_film(η), both at wi·h, and the diffuse base's weight
//   (1 − w)(1 − s F_max F0d(wi·h)) + w (1 − R_film(η, |cos θo|)),
// per channel: the base keeps what the film does not reflect towards the viewer, as the
// clear coat and the sheen scale theirs by their albedo at wo (clearcoat.h, sheen.h), and
// like theirs the layering is not reciprocal. A white furnace then reflects 1 − R_film(θo)
// plus the lobe's albedo, which is R_film averaged over the lobe's facets (wi·h = wo·h,
// near cos θo) less shadowing: within 0.1 % above 1 and 2 % below it for a 250 nm film
// at 0°–45° (tests/bsdf/thin_film_test.cpp). The extension weights the base by
// 1 − max(R_film(wi·h)), the largest RGB component: that form gains energy wherever R_film
// at wi·h falls below its value at the viewing angle (up to 9 % for the same film), and
// dims the base evenly where a lossless film passes the complement of its colour.
//
// Sampling picks the specular lobe with probability p_s = E_s / (E_s + E_d) from
// albedo estimates at wo (E_s = mean F_F0(cos θo), E_d = (1 − m) mean(c) (1 − F_0.04(cos θo)))
// and pdf() is the matching one-sample mixture p_s p_spec + (1 − p_s) p_diffuse. A lobe is
// given probability 0 only when its f is identically 0. Two-sided.
#include <algorithm>
#include <numbers>
#include <optional>
#include <utility>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/fresnel.h"
#include "prism/bsdf/microfacet.h"
#include "prism/bsdf/thin_film.h"
#include "prism/sampling/warps.h"

namespace prism::bsdf {

template <int N>
struct MetallicRoughness {
  static constexpr float kDielectricF0 = 0.04f;  // glTF 2.0: IOR 1.5
  static constexpr float kMinAlpha = 2e-3f;

  color::SampledSpectrum<N> base_color{0.8f};
  float metallic = 0.0f;
  MicrofacetDistribution distribution = MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.25f);
  color::SampledSpectrum<N> dielectric_f0{kDielectricF0};  // F0d per channel, in [0, 1]
  float dielectric_f0_max = kDielectricF0;                 // max F0d of its RGB colour
  float specular_weight = 1.0f;                            // s, in [0, 1]
  ThinFilm<N> film{};                                      // iridescence; weight 0: none

  // A grey F0d.
  static MetallicRoughness from_roughness(const color::SampledSpectrum<N>& base, float metallic,
                                          float perceptual_roughness, float dielectric_f0 = kDielectricF0,
                                          float specular_weight = 1.0f) {
    return from_roughness(base, metallic, perceptual_roughness, color::SampledSpectrum<N>(dielectric_f0),
                          dielectric_f0, specular_weight);
  }
  // A coloured F0d (KHR_materials_specular's specularColorFactor): per channel, with the
  // largest component of its RGB colour.
  static MetallicRoughness from_roughness(const color::SampledSpectrum<N>& base, float metallic,
                                          float perceptual_roughness, const color::SampledSpectrum<N>& dielectric_f0,
                                          float dielectric_f0_max, float specular_weight) {
    const float alpha = std::max(kMinAlpha, perceptual_roughness * perceptual_roughness);
    return {base,          metallic,          MicrofacetDistribution::isotropic(MicrofacetType::ggx, alpha),
            dielectric_f0, dielectric_f0_max, specular_weight};
  }

  color::SampledSpectrum<N> f0() const { return dielectric_f0 * (1.0f - metallic) + base_color * metallic; }
  // The bracket above: the specular lobe's Fresnel colour at cos θ = wi·h.
  color::SampledSpectrum<N> specular_fresnel(float cos_theta) const {
    if (specular_weight == 1.0f) return fresnel_schlick(f0(), cos_theta);
    return fresnel_schlick(base_color, cos_theta) * metallic +
           fresnel_schlick(dielectric_f0, cos_theta) * ((1.0f - metallic) * specular_weight);
  }
  // The diffuse lobe's weight 1 − s F_max F0d, without (1 − m).
  float diffuse_transmission(float cos_theta) const {
    return 1.0f - specular_weight * fresnel_schlick(dielectric_f0_max, cos_theta);
  }

  // With a film: the bracket at cos θ = wi·h, given the film's reflectance there, per
  // channel.
  color::SampledSpectrum<N> filmed_specular_fresnel(float cos_theta, const color::SampledSpectrum<N>& over_dielectric,
                                                    const color::SampledSpectrum<N>& over_metal) const {
    const float w = film.weight;
    color::SampledSpectrum<N> specular =
        (fresnel_schlick(dielectric_f0, cos_theta) * ((1.0f - w) * specular_weight) + over_dielectric * w) *
        (1.0f - metallic);
    if (metallic > 0.0f)
      specular += (fresnel_schlick(base_color, cos_theta) * (1.0f - w) + over_metal * w) * metallic;
    return specular;
  }
  // The diffuse weight (without (1 − m)) at cos θ = wi·h, given the film's reflectance
  // towards the viewer.
  color::SampledSpectrum<N> filmed_diffuse_weight(float cos_theta,
                                                  const color::SampledSpectrum<N>& reflected_to_viewer) const {
    const float w = film.weight;
    return color::SampledSpectrum<N>((1.0f - w) * diffuse_transmission(cos_theta) + w) - reflected_to_viewer * w;
  }

  // Albedo estimates of the two lobes at |cos θo| (channel means): specular, diffuse.
  std::pair<float, float> albedo_estimates(float cos_o) const {
    if (__builtin_expect(film.present(), 0)) {
      // The film's reflectance at θo stands in for its average over the lobe's facets and
      // the diffuse directions (an estimate: only the sampling probabilities use it).
      const auto& at_wo = film.at_wo(cos_o, metallic > 0.0f);
      return {filmed_specular_fresnel(cos_o, at_wo.over_dielectric, at_wo.over_metal).average(),
              (1.0f - metallic) * (base_color * filmed_diffuse_weight(cos_o, at_wo.over_dielectric)).average()};
    }
    return {specular_fresnel(cos_o).average(), (1.0f - metallic) * base_color.average() * diffuse_transmission(cos_o)};
  }
  float albedo_estimate(float cos_o) const {
    const auto [e_spec, e_diff] = albedo_estimates(cos_o);
    return e_spec + e_diff;
  }

  // Probability of sampling the specular lobe for this wo.
  float specular_probability(const Vec3f& wo) const {
    const auto [e_spec, e_diff] = albedo_estimates(abs_cos_theta(wo));
    return e_spec + e_diff > 0.0f ? e_spec / (e_spec + e_diff) : 1.0f;
  }

  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi) const {
    const auto r = upper_reflection(wo, wi);
    if (!r) return {};
    const Vec3f &o = r->o, &i = r->i, &h = r->h;
    const float i_h = dot(i, h);
    const float spec = distribution.D(h) * distribution.G2(o, i) / (4.0f * o.z * i.z);
    if (__builtin_expect(film.present(), 0)) {
      const color::SampledSpectrum<N> diffuse =
          filmed_diffuse_weight(i_h, film.at_wo(o.z, metallic > 0.0f).over_dielectric);
      return base_color * diffuse * ((1.0f - metallic) * std::numbers::inv_pi_v<float>) +
             filmed_specular_fresnel(i_h, film.over_dielectric(i_h),
                                     metallic > 0.0f ? film.over_metal(i_h) : color::SampledSpectrum<N>(0.0f)) *
                 spec;
    }
    const float diffuse_weight = (1.0f - metallic) * diffuse_transmission(i_h) * std::numbers::inv_pi_v<float>;
    return base_color * diffuse_weight + specular_fresnel(i_h) * spec;
  }

  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    const auto r = upper_reflection(wo, wi);
    if (!r) return 0.0f;
    const Vec3f &o = r->o, &i = r->i, &h = r->h;
    const float p_s = specular_probability(o);
    const float p_spec = distribution.pdf_microfacet_normal(o, h) * reflection_jacobian(o, h);
    return p_s * p_spec + (1.0f - p_s) * cosine_hemisphere_pdf(i.z);
  }

  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const Vec3f o = wo.z < 0.0f ? flip_z(wo) : wo;
    Vec3f i;
    if (u_lobe < specular_probability(o)) {
      i = reflect(o, distribution.sample_microfacet_normal(o, u));
      if (i.z <= 0.0f) return std::nullopt;
    } else {
      i = sample_cosine_hemisphere(u);
    }
    BsdfSample<N> s;
    s.wi = wo.z < 0.0f ? flip_z(i) : i;
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.f = eval(wo, s.wi);
    return s;
  }
};

}  // namespace prism::bsdf
