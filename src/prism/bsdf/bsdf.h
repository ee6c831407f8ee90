#pragma once
// The BSDF of a shading point: a closed set of lobes dispatched statically (std::variant,
// no virtual calls), all in the local shading frame (z = shading normal; the caller maps
// with prism::Frame). eval/sample/pdf agree: sample() draws wi with density pdf(wo, wi)
// and returns f = eval(wo, wi) (cosine not included); see bsdf_sample.h for the delta-lobe
// and throughput conventions and dielectric.h for dispersion and the η² convention.
#include <optional>
#include <type_traits>
#include <variant>

#include "prism/bsdf/bsdf_sample.h"
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

  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi,
                                 TransportMode mode = TransportMode::radiance) const {
    return std::visit(
        [&](const auto& l) {
          if constexpr (std::is_same_v<std::decay_t<decltype(l)>, Dielectric<N>>) return l.eval(wo, wi, mode);
          else return l.eval(wo, wi);
        },
        lobe);
  }
  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    return std::visit([&](const auto& l) { return l.pdf(wo, wi); }, lobe);
  }
  // u_lobe picks among lobes / reflection vs refraction; u drives the direction.
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f u,
                                      TransportMode mode = TransportMode::radiance) const {
    return std::visit(
        [&](const auto& l) {
          if constexpr (std::is_same_v<std::decay_t<decltype(l)>, Dielectric<N>>) return l.sample(wo, u_lobe, u, mode);
          else return l.sample(wo, u_lobe, u);
        },
        lobe);
  }
  // Every lobe is a delta: NEE and MIS are pointless at this vertex.
  bool is_specular() const {
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
  // Which of sample()'s numbers the lobe reads, so callers can skip drawing the others:
  // the single-component lobes never choose with u_lobe; a mirror needs no direction
  // number. Listed by exclusion, so that a lobe added later draws every number (safe)
  // until it is listed here.
  bool uses_lobe_sample() const {
    return !std::holds_alternative<Lambertian<N>>(lobe) && !std::holds_alternative<SpecularReflection<N>>(lobe) &&
           !std::holds_alternative<RoughConductor<N>>(lobe);
  }
  bool uses_direction_sample() const { return !std::holds_alternative<SpecularReflection<N>>(lobe); }
  // The integrator must terminate secondary wavelengths before shading (dielectric.h).
  bool is_dispersive() const {
    const auto* d = std::get_if<Dielectric<N>>(&lobe);
    return d != nullptr && d->is_dispersive();
  }
};

extern template struct Bsdf<3>;
extern template struct Bsdf<4>;
extern template struct Bsdf<8>;

}  // namespace prism::bsdf
