#pragma once
// The BSDF of a shading point: a closed set of lobes dispatched statically (std::variant,
// no virtual calls), all in the local shading frame (z = shading normal; the caller maps
// with prism::Frame), optionally under a clear coat (clearcoat.h). eval/sample/pdf agree:
// sample() draws wi with density pdf(wo, wi) and returns f = eval(wo, wi) (cosine not
// included); see bsdf_sample.h for the delta-lobe and throughput conventions and
// dielectric.h for dispersion and the η² convention.
//
// With a coat, sample() is a one-sample mixture: the coat with probability
// p_c = A_c / (A_c + (1 − A_c) a_base) (A_c the coat's albedo at wo, a_base an estimate of
// the base's), else the base; pdf() is p_c p_coat + (1 − p_c) p_base over the non-delta
// parts. A smooth coat is a delta lobe next to a non-delta base: a sample from it is flagged
// is_specular with pdf p_c, and eval()/pdf() leave it out, as bsdf_sample.h says of deltas.
#include <algorithm>
#include <optional>
#include <type_traits>
#include <variant>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/clearcoat.h"
#include "prism/bsdf/dielectric.h"
#include "prism/bsdf/lambertian.h"
#include "prism/bsdf/metallic_roughness.h"
#include "prism/bsdf/rough_conductor.h"
#include "prism/bsdf/specular_reflection.h"
#include "prism/bsdf/thin_dielectric.h"

namespace prism::bsdf {

template <int N>
struct Bsdf {
  using Lobe = std::variant<Lambertian<N>, SpecularReflection<N>, RoughConductor<N>,
                            Dielectric<N>, MetallicRoughness<N>, ThinDielectric<N>>;
  Lobe lobe;
  // On reflective lobes only (the material layer never coats a dielectric); weight 0: none.
  Clearcoat coat{};

  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi,
                                 TransportMode mode = TransportMode::radiance) const {
    if (__builtin_expect(!coat.present(), 1)) return lobe_eval(wo, wi, mode);
    return coated_eval(wo, wi, mode, coat.albedo(wo));
  }
  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (__builtin_expect(!coat.present(), 1)) return lobe_pdf(wo, wi);
    return coated_pdf(wo, wi, coat_probability(wo, coat.albedo(wo)));
  }
  // u_lobe picks among lobes / reflection vs refraction; u drives the direction.
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f u,
                                      TransportMode mode = TransportMode::radiance) const {
    if (__builtin_expect(!coat.present(), 1)) return lobe_sample(wo, u_lobe, u, mode);
    return coated_sample(wo, u_lobe, u, mode);
  }
  // Every lobe is a delta: NEE and MIS are pointless at this vertex.
  bool is_specular() const { return lobe_is_specular() && (!coat.present() || coat.is_smooth()); }
  // Which of sample()'s numbers the lobe reads, so callers can skip drawing the others:
  // the single-component lobes never choose with u_lobe; a mirror needs no direction
  // number. Listed by exclusion, so that a lobe added later draws every number (safe)
  // until it is listed here.
  bool uses_lobe_sample() const {
    return coat.present() || (!std::holds_alternative<Lambertian<N>>(lobe) &&
                              !std::holds_alternative<SpecularReflection<N>>(lobe) &&
                              !std::holds_alternative<RoughConductor<N>>(lobe));
  }
  bool uses_direction_sample() const {
    return !std::holds_alternative<SpecularReflection<N>>(lobe) || (coat.present() && !coat.is_smooth());
  }
  // The integrator must terminate secondary wavelengths before shading (dielectric.h).
  bool is_dispersive() const {
    const auto* d = std::get_if<Dielectric<N>>(&lobe);
    return d != nullptr && d->is_dispersive();
  }

  // Probability that a coated sample() draws from the coat, given the coat's albedo at wo.
  float coat_probability(const Vec3f& wo, float a_coat) const {
    // The floor keeps the base sampled at least now and then even where the estimate says
    // it reflects nothing at this wo (a black metal at normal incidence still reflects at
    // other angles): a lobe gets probability 0 only if its f is identically 0.
    const float a_base = std::max(0.02f, base_albedo_estimate(wo));
    return a_coat / (a_coat + (1.0f - a_coat) * a_base);
  }

 private:
  // The coated eval and pdf, given what sample() has already computed at wo: the coat's
  // albedo A_c (the base's weight is 1 − A_c) and the mixture probability.
  color::SampledSpectrum<N> coated_eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode, float a_coat) const {
    return lobe_eval(wo, wi, mode) * (1.0f - a_coat) + color::SampledSpectrum<N>(coat.eval(wo, wi));
  }
  float coated_pdf(const Vec3f& wo, const Vec3f& wi, float p_coat) const {
    return p_coat * coat.pdf(wo, wi) + (1.0f - p_coat) * lobe_pdf(wo, wi);
  }
  color::SampledSpectrum<N> lobe_eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
    return std::visit(
        [&](const auto& l) {
          if constexpr (std::is_same_v<std::decay_t<decltype(l)>, Dielectric<N>>) return l.eval(wo, wi, mode);
          else return l.eval(wo, wi);
        },
        lobe);
  }
  float lobe_pdf(const Vec3f& wo, const Vec3f& wi) const {
    return std::visit([&](const auto& l) { return l.pdf(wo, wi); }, lobe);
  }
  std::optional<BsdfSample<N>> lobe_sample(const Vec3f& wo, float u_lobe, Vec2f u, TransportMode mode) const {
    return std::visit(
        [&](const auto& l) {
          if constexpr (std::is_same_v<std::decay_t<decltype(l)>, Dielectric<N>>) return l.sample(wo, u_lobe, u, mode);
          else return l.sample(wo, u_lobe, u);
        },
        lobe);
  }
  bool lobe_is_specular() const {
    return std::visit(
        [](const auto& l) {
          using T = std::decay_t<decltype(l)>;
          if constexpr (std::is_same_v<T, SpecularReflection<N>> || std::is_same_v<T, ThinDielectric<N>>) return true;
          else if constexpr (std::is_same_v<T, RoughConductor<N>> || std::is_same_v<T, Dielectric<N>>)
            return l.is_specular();
          else return false;
        },
        lobe);
  }
  // The base's reflectance from wo, roughly: its Fresnel or albedo term averaged over the
  // channels (only sampling probabilities depend on it).
  float base_albedo_estimate(const Vec3f& wo) const {
    const float cos_o = abs_cos_theta(wo);
    return std::visit(
        [&](const auto& l) {
          using T = std::decay_t<decltype(l)>;
          if constexpr (std::is_same_v<T, Lambertian<N>> || std::is_same_v<T, SpecularReflection<N>>)
            return l.reflectance.average();
          else if constexpr (std::is_same_v<T, RoughConductor<N>>) return l.fresnel(cos_o).average();
          else if constexpr (std::is_same_v<T, MetallicRoughness<N>>) return l.albedo_estimate(cos_o);
          else return 1.0f;
        },
        lobe);
  }
  std::optional<BsdfSample<N>> coated_sample(const Vec3f& wo, float u_lobe, Vec2f u, TransportMode mode) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float a_coat = coat.albedo(wo);
    const float p_coat = coat_probability(wo, a_coat);
    if (u_lobe < p_coat) {
      const auto wi = coat.sample_direction(wo, u);
      if (!wi) return std::nullopt;
      BsdfSample<N> s;
      s.wi = *wi;
      if (coat.is_smooth()) {
        s.f = color::SampledSpectrum<N>(a_coat / abs_cos_theta(s.wi));
        s.pdf = p_coat;
        s.is_specular = true;
        return s;
      }
      s.pdf = coated_pdf(wo, s.wi, p_coat);
      if (!(s.pdf > 0.0f)) return std::nullopt;
      s.f = coated_eval(wo, s.wi, mode, a_coat);
      return s;
    }
    // The rest of u_lobe, rescaled to [0, 1), chooses within the base.
    const float u_base = std::min((u_lobe - p_coat) / (1.0f - p_coat), 0x1.fffffep-1f);
    auto s = lobe_sample(wo, u_base, u, mode);
    if (!s) return s;
    if (s->is_specular) {
      s->f *= 1.0f - a_coat;
      s->pdf *= 1.0f - p_coat;
      return s;
    }
    s->pdf = coated_pdf(wo, s->wi, p_coat);
    if (!(s->pdf > 0.0f)) return std::nullopt;
    s->f = coated_eval(wo, s->wi, mode, a_coat);
    return s;
  }
};

extern template struct Bsdf<3>;
extern template struct Bsdf<4>;
extern template struct Bsdf<8>;

}  // namespace prism::bsdf
