#pragma once
// The BSDF of a shading point: a closed set of lobes dispatched statically (std::variant,
// no virtual calls), all in the local shading frame (z = shading normal; the caller maps
// with prism::Frame), optionally under a clear coat (clearcoat.h). eval/sample/pdf agree:
// sample() draws wi with density pdf(wo, wi) and returns f = eval(wo, wi) (cosine not
// included); see bsdf_sample.h for the delta-lobe and throughput conventions and
// dielectric.h for dispersion and the η² convention.
//
// Layers, top down: an optional clear coat (clearcoat.h) over an optional sheen (sheen.h)
// over the lobe, as glTF stacks KHR_materials_clearcoat over KHR_materials_sheen. The coat
// sees "the base" = the sheen over the lobe (base_eval/base_pdf/base_sample below); each
// layer is a one-sample mixture of itself and what lies under it, alike.
//
// With a coat, sample() is a one-sample mixture: the coat with probability
// p_c = A_c / (A_c + (1 − A_c) a_base) (A_c the coat's albedo at wo, a_base an estimate of
// the base's), else the base; pdf() is p_c p_coat + (1 − p_c) p_base over the non-delta
// parts. A smooth coat is a delta lobe next to a non-delta base: a sample from it is flagged
// is_specular with pdf p_c, and eval()/pdf() leave it out, as bsdf_sample.h says of deltas.
#include <algorithm>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/clearcoat.h"
#include "prism/bsdf/dielectric.h"
#include "prism/bsdf/lambertian.h"
#include "prism/bsdf/metallic_roughness.h"
#include "prism/bsdf/rough_conductor.h"
#include "prism/bsdf/sheen.h"
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
  // Likewise; colour 0: none.
  Sheen<N> sheen{};

  // eval and pdf, and the layers' and lobe's own, are inlined down to the lobe; what only
  // coated, sheened or non-diffuse BSDFs run is not (see lobe_eval).
  [[gnu::always_inline]] color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi,
                                                        TransportMode mode = TransportMode::radiance) const {
    if (__builtin_expect(!coat.present(), 1)) return base_eval(wo, wi, mode);
    return coated_eval(wo, wi, mode, coat.albedo(wo));
  }
  [[gnu::always_inline]] float pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (__builtin_expect(!coat.present(), 1)) return base_pdf(wo, wi);
    return coated_pdf(wo, wi, coat_probability(wo, coat.albedo(wo)));
  }
  // eval, and pdf into `pdf_out` where `want_pdf` and the value is not black (what a light
  // sample's MIS weight needs; `pdf_out` is left alone otherwise).
  [[gnu::always_inline]] color::SampledSpectrum<N> eval_with_pdf(const Vec3f& wo, const Vec3f& wi, bool want_pdf,
                                                                float& pdf_out) const {
    const color::SampledSpectrum<N> f = eval(wo, wi);
    if (want_pdf && !f.is_black()) pdf_out = pdf(wo, wi);
    return f;
  }
  // u_lobe picks among lobes / reflection vs refraction; u drives the direction.
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f u,
                                      TransportMode mode = TransportMode::radiance) const {
    if (__builtin_expect(!coat.present(), 1)) return base_sample(wo, u_lobe, u, mode);
    return coated_sample(wo, u_lobe, u, mode);
  }
  // Every lobe is a delta: NEE and MIS are pointless at this vertex.
  bool is_specular() const {
    return lobe_is_specular() && !sheen.present() && (!coat.present() || coat.is_smooth());
  }
  // Which of sample()'s numbers the lobe reads, so callers can skip drawing the others:
  // the single-component lobes never choose with u_lobe; a mirror needs no direction
  // number. Listed by exclusion, so that a lobe added later draws every number (safe)
  // until it is listed here.
  bool uses_lobe_sample() const {
    return coat.present() || sheen.present() || (!std::holds_alternative<Lambertian<N>>(lobe) &&
                              !std::holds_alternative<SpecularReflection<N>>(lobe) &&
                              !std::holds_alternative<RoughConductor<N>>(lobe));
  }
  bool uses_direction_sample() const {
    return !std::holds_alternative<SpecularReflection<N>>(lobe) || (coat.present() && !coat.is_smooth()) ||
           sheen.present();
  }
  // The integrator must terminate secondary wavelengths before shading (dielectric.h).
  bool is_dispersive() const {
    const auto* d = std::get_if<Dielectric<N>>(&lobe);
    return d != nullptr && d->is_dispersive();
  }

  // Probability that a coated sample() draws from the coat, given the coat's albedo at wo.
  float coat_probability(const Vec3f& wo, float a_coat) const {
    return top_layer_probability(a_coat, base_albedo_estimate(wo));
  }
  // Probability that a sheened sample draws from the sheen, given its mean albedo at wo.
  float sheen_probability(const Vec3f& wo, float a_sheen) const {
    return top_layer_probability(a_sheen, lobe_albedo_estimate(wo));
  }
  // A layer of albedo a_top over what lies below, whose albedo is estimated as a_below: the
  // top is chosen in proportion to what it reflects, a_top : (1 − a_top) a_below. The floor
  // keeps what lies below sampled now and then even where the estimate says it reflects
  // nothing at this wo (a black metal at normal incidence still reflects at other angles):
  // a layer gets probability 0 only if its f is identically 0.
  static float top_layer_probability(float a_top, float a_below) {
    return a_top / (a_top + (1.0f - a_top) * std::max(0.02f, a_below));
  }

 private:
  // The coated eval and pdf, given what sample() has already computed at wo: the coat's
  // albedo A_c (the base's weight is 1 − A_c) and the mixture probability.
  [[gnu::noinline]] color::SampledSpectrum<N> coated_eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode,
                                                         float a_coat) const {
    return base_eval(wo, wi, mode) * (1.0f - a_coat) + color::SampledSpectrum<N>(coat.eval(wo, wi));
  }
  [[gnu::noinline]] float coated_pdf(const Vec3f& wo, const Vec3f& wi, float p_coat) const {
    return p_coat * coat.pdf(wo, wi) + (1.0f - p_coat) * base_pdf(wo, wi);
  }
  // The base under the coat: the sheen over the lobe, or the lobe alone.
  [[gnu::always_inline]] color::SampledSpectrum<N> base_eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
    if (__builtin_expect(!sheen.present(), 1)) return lobe_eval(wo, wi, mode);
    return sheened_eval(wo, wi, mode, sheen.albedo(wo));
  }
  [[gnu::always_inline]] float base_pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (__builtin_expect(!sheen.present(), 1)) return lobe_pdf(wo, wi);
    return sheened_pdf(wo, wi, sheen_probability(wo, sheen.albedo(wo).average()));
  }
  std::optional<BsdfSample<N>> base_sample(const Vec3f& wo, float u_lobe, Vec2f u, TransportMode mode) const {
    if (__builtin_expect(!sheen.present(), 1)) return lobe_sample(wo, u_lobe, u, mode);
    return sheened_sample(wo, u_lobe, u, mode);
  }
  // The sheened eval and pdf, given the sheen's albedo A_s per channel (the lobe's weight
  // is 1 − A_s) and the mixture probability.
  [[gnu::noinline]] color::SampledSpectrum<N> sheened_eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode,
                                                          const color::SampledSpectrum<N>& a_sheen) const {
    return lobe_eval(wo, wi, mode) * (color::SampledSpectrum<N>(1.0f) - a_sheen) + sheen.eval(wo, wi);
  }
  [[gnu::noinline]] float sheened_pdf(const Vec3f& wo, const Vec3f& wi, float p_sheen) const {
    return p_sheen * sheen.pdf(wo, wi) + (1.0f - p_sheen) * lobe_pdf(wo, wi);
  }
  std::optional<BsdfSample<N>> sheened_sample(const Vec3f& wo, float u_lobe, Vec2f u, TransportMode mode) const {
    if (wo.z == 0.0f) return std::nullopt;
    const color::SampledSpectrum<N> a_sheen = sheen.albedo(wo);
    const float p_sheen = sheen_probability(wo, a_sheen.average());
    const auto eval = [&](const Vec3f& wi) { return sheened_eval(wo, wi, mode, a_sheen); };
    const auto pdf = [&](const Vec3f& wi) { return sheened_pdf(wo, wi, p_sheen); };
    if (u_lobe < p_sheen) {
      const auto wi = sheen.sample_direction(wo, u);
      if (!wi) return std::nullopt;
      BsdfSample<N> s;
      s.wi = *wi;
      return with_mixture(s, eval, pdf);
    }
    return sample_below(u_lobe, p_sheen, color::SampledSpectrum<N>(1.0f) - a_sheen,
                        [&](float u_rest) { return lobe_sample(wo, u_rest, u, mode); }, eval, pdf);
  }
  // A one-sample mixture's non-delta sample, given the mixture's f and pdf (what NEE and MIS
  // evaluate, so sample() must return them).
  template <class Eval, class Pdf>
  static std::optional<BsdfSample<N>> with_mixture(std::optional<BsdfSample<N>> s, const Eval& eval, const Pdf& pdf) {
    if (!s) return s;
    s->pdf = pdf(s->wi);
    if (!(s->pdf > 0.0f)) return std::nullopt;
    s->f = eval(s->wi);
    return s;
  }
  // A mixture's sample of what lies below its top layer (chosen with probability p_top,
  // u_lobe ≥ p_top), drawn with the rest of u_lobe rescaled to [0, 1): a delta sample keeps
  // its direction, scaled by the weight the top layer passes on and by the choice's
  // probability; any other takes the mixture's f and pdf.
  template <class SampleBelow, class Eval, class Pdf>
  static std::optional<BsdfSample<N>> sample_below(float u_lobe, float p_top, const color::SampledSpectrum<N>& passed_on,
                                                   const SampleBelow& sample, const Eval& eval, const Pdf& pdf) {
    auto s = sample(std::min((u_lobe - p_top) / (1.0f - p_top), 0x1.fffffep-1f));
    if (s && s->is_specular) {
      s->f *= passed_on;
      s->pdf *= 1.0f - p_top;
      return s;
    }
    return with_mixture(std::move(s), eval, pdf);
  }
  // The diffuse lobe, the commonest, is called directly: std::visit's dispatch and the copy
  // of its result out of the visitor cost a quarter of a Lambertian sample's instructions,
  // and an eval or pdf that kept the visitor inline was too large to inline into the
  // integrator (Callgrind; docs/performance-design.md "Instruction cuts"). The same calls as the visitor
  // makes.
  [[gnu::always_inline]] color::SampledSpectrum<N> lobe_eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
    if (const auto* diffuse = std::get_if<Lambertian<N>>(&lobe)) return diffuse->eval(wo, wi);
    return visited_lobe_eval(wo, wi, mode);
  }
  [[gnu::noinline]] color::SampledSpectrum<N> visited_lobe_eval(const Vec3f& wo, const Vec3f& wi,
                                                               TransportMode mode) const {
    return std::visit(
        [&](const auto& l) {
          if constexpr (std::is_same_v<std::decay_t<decltype(l)>, Dielectric<N>>) return l.eval(wo, wi, mode);
          else return l.eval(wo, wi);
        },
        lobe);
  }
  [[gnu::always_inline]] float lobe_pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (const auto* diffuse = std::get_if<Lambertian<N>>(&lobe)) return diffuse->pdf(wo, wi);
    return visited_lobe_pdf(wo, wi);
  }
  [[gnu::noinline]] float visited_lobe_pdf(const Vec3f& wo, const Vec3f& wi) const {
    return std::visit([&](const auto& l) { return l.pdf(wo, wi); }, lobe);
  }
  std::optional<BsdfSample<N>> lobe_sample(const Vec3f& wo, float u_lobe, Vec2f u, TransportMode mode) const {
    if (const auto* diffuse = std::get_if<Lambertian<N>>(&lobe)) return diffuse->sample(wo, u_lobe, u);
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
  // The base's reflectance from wo, roughly (only sampling probabilities depend on it):
  // the sheen's albedo plus what it leaves to the lobe.
  float base_albedo_estimate(const Vec3f& wo) const {
    if (__builtin_expect(!sheen.present(), 1)) return lobe_albedo_estimate(wo);
    const float a_sheen = sheen.albedo(wo).average();
    return a_sheen + (1.0f - a_sheen) * lobe_albedo_estimate(wo);
  }
  // The lobe's: its Fresnel or albedo term averaged over the channels.
  float lobe_albedo_estimate(const Vec3f& wo) const {
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
    const auto eval = [&](const Vec3f& wi) { return coated_eval(wo, wi, mode, a_coat); };
    const auto pdf = [&](const Vec3f& wi) { return coated_pdf(wo, wi, p_coat); };
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
      return with_mixture(s, eval, pdf);
    }
    return sample_below(u_lobe, p_coat, color::SampledSpectrum<N>(1.0f - a_coat),
                        [&](float u_rest) { return base_sample(wo, u_rest, u, mode); }, eval, pdf);
  }
};

extern template struct Bsdf<3>;
extern template struct Bsdf<4>;
extern template struct Bsdf<8>;

}  // namespace prism::bsdf
