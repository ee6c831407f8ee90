#pragma once
// A sheen: the back-scattering of a velvet-like layer of fibres over a reflective base, as
// in glTF's KHR_materials_sheen (Estevez & Kulla 2017, "Production Friendly Microfacet
// Sheen BRDF"):
//   f = f_sheen + (1 − Ê(|cos θo|) c) f_base,   f_sheen = c D(h) V(wo, wi) / Ê_n(|cos θo|),
// per wavelength (channel), with c the sheen colour, D the "Charlie" distribution
// (2 + 1/α) sin^(1/α) θh / 2π at α = r² (r the sheen roughness), and V the visibility of
// the paper's fitted Λ, 1 / ((1 + Λ(cos θo) + Λ(cos θi)) 4 |cos θo| |cos θi|). E is the
// lobe's directional albedo at c = 1 (tabulated below), Ê = min(E, 1) and Ê_n = max(E, 1).
//
// Two departures from the extension, both for energy:
//  - The base is scaled per channel by 1 − c Ê, not by 1 − max(c) E: with a white base a
//    white furnace then stays at 1 for any sheen colour (the extension's max loses the
//    difference), as Kulla & Conty's albedo scaling intends.
//  - The fitted Λ lets the smoothest sheens reflect more than they receive at grazing
//    views (E = 2.3 at r = 0.05, cos θo = 0.02; 1.05 at r = 0.2): the lobe is divided by
//    max(E, 1) there, so the layer never gains energy.
// The sheen roughness is floored at kMinPerceptualRoughness (0.1), where the table and its
// quadrature still resolve the lobe; glTF's default r = 0 renders as 0.1.
//
// The layering is not reciprocal (the base is weighted by wo only), like the clear coat's
// (clearcoat.h); camera paths evaluate it with wo towards the camera. The lobe is sampled
// uniformly over wo's hemisphere: the Charlie distribution has no closed-form inverse, and
// the lobe is broad (it peaks at grazing, where cosine sampling would starve it).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "prism/bsdf/bsdf_sample.h"

namespace prism::bsdf {

inline constexpr float kMinSheenPerceptualRoughness = 0.1f;

// f_sheen / c for directions in the upper hemisphere (cos θ > 0 both), α = r².
float charlie_sheen_brdf(const Vec3f& wo, const Vec3f& wi, float alpha);
// Its parts: Λ(cos θ) of the fitted visibility (cos θ > 0), and D(h) V(wo, wi) given Λ at
// both directions (both above the surface).
float sheen_lambda(float cos_theta, float alpha);
float charlie_sheen(const Vec3f& wo, const Vec3f& wi, float alpha, float lambda_o, float lambda_i);
// E(μ, r) = ∫ charlie_sheen_brdf cos θi dωi over the upper hemisphere, from a direction with
// |cos θ| = cos_theta, r ∈ [kMinSheenPerceptualRoughness, 1] (clamped): tabulated on first
// use on a 32 × 32 grid (nodes at μ = (i/31)², dense at grazing where E changes fastest)
// by a midpoint rule, and bilinearly interpolated in (√μ, r).
float sheen_directional_albedo(float cos_theta, float perceptual_roughness);

template <int N>
struct Sheen {
  color::SampledSpectrum<N> color{0.0f};  // c per channel, in [0, 1]
  float perceptual_roughness = kMinSheenPerceptualRoughness;
  float alpha = kMinSheenPerceptualRoughness * kMinSheenPerceptualRoughness;
  bool active = false;

  static Sheen make(const color::SampledSpectrum<N>& color, float perceptual_roughness) {
    Sheen s;
    for (int i = 0; i < N; ++i) s.color[i] = std::clamp(color[i], 0.0f, 1.0f);
    s.perceptual_roughness = std::clamp(perceptual_roughness, kMinSheenPerceptualRoughness, 1.0f);
    s.alpha = s.perceptual_roughness * s.perceptual_roughness;
    s.active = !s.color.is_black();
    return s;
  }

  bool present() const { return active; }

  // c Ê(|cos θo|) per channel: what the sheen reflects of light from wo; the base under it
  // gets 1 − c Ê.
  color::SampledSpectrum<N> albedo(const Vec3f& wo) const {
    return color * std::min(at_wo(abs_cos_theta(wo)).albedo, 1.0f);
  }
  // f_sheen (cosine not included); 0 on opposite sides or at the horizon.
  color::SampledSpectrum<N> eval(const Vec3f& wo, const Vec3f& wi) const {
    if (!same_hemisphere(wo, wi)) return color::SampledSpectrum<N>(0.0f);
    const Vec3f o = wo.z < 0.0f ? flip_z(wo) : wo, i = wo.z < 0.0f ? flip_z(wi) : wi;
    const AtWo& w = at_wo(o.z);
    const float normalisation = std::max(w.albedo, 1.0f);
    return color * (charlie_sheen(o, i, alpha, w.lambda_o, sheen_lambda(i.z, alpha)) / normalisation);
  }
  // Uniform over wo's hemisphere: 1/2π there.
  float pdf(const Vec3f& wo, const Vec3f& wi) const {
    return same_hemisphere(wo, wi) ? 0.5f * std::numbers::inv_pi_v<float> : 0.0f;
  }
  // What depends on wo alone, E(|cos θo|) and Λ(|cos θo|), kept for the vertex's next call:
  // a shading vertex asks for the albedo, f and pdf several times with one wo (sampling,
  // NEE, MIS). A BSDF is one vertex's, on one thread; a copy carries the cache along.
  struct AtWo {
    float cos_o = -1.0f;  // none yet
    float albedo = 0.0f;
    float lambda_o = 0.0f;
  };
  mutable AtWo at_wo_;
  const AtWo& at_wo(float cos_o) const {
    if (cos_o != at_wo_.cos_o)
      at_wo_ = {cos_o, sheen_directional_albedo(cos_o, perceptual_roughness), sheen_lambda(cos_o, alpha)};
    return at_wo_;
  }

  std::optional<Vec3f> sample_direction(const Vec3f& wo, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float z = std::max(u.x, 1e-7f);  // cos θ uniform in (0, 1]: uniform solid angle
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * std::numbers::pi_v<float> * u.y;
    return Vec3f(r * std::cos(phi), r * std::sin(phi), wo.z < 0.0f ? -z : z);
  }
};

}  // namespace prism::bsdf
