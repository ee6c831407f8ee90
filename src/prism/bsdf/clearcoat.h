#pragma once
// A clear coat: a colourless dielectric layer (η = 1.5) on top of a reflective base BSDF,
// as in glTF's KHR_materials_clearcoat:
//   f = c f_coat + (1 − c E(|cos θo|)) f_base,
// with c the coat's weight (clearcoatFactor), f_coat the GGX microfacet reflection of the
// coat (α = r², r its perceptual roughness) with the exact dielectric Fresnel term, and E
// the coat's directional albedo ∫ f_coat cos θi dωi: the fraction of light arriving from
// wo that the coat reflects, so the base only sees the rest.
//
// For a smooth coat E is the Fresnel reflectance F(cos θo) and f is the extension's own
// formula, mix(base, coat, c F(N·V)) (KHR_materials_clearcoat, "Clearcoat Layering"). For a
// rough coat the extension still weights by F(N·V), which lets a white base under a rough
// coat reflect more than it receives; weighting by the albedo instead ("albedo scaling",
// Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks", §layering) keeps
// a white furnace at exactly 1 for a white Lambertian base and below 1 for every other.
// E(μ, r) is tabulated once per process (coat_directional_albedo below).
//
// Like the extension, the layering is not reciprocal (the base is weighted by wo only) and
// ignores refraction into the coat and reflections inside it; camera paths (the only ones
// Prism traces) evaluate it with wo towards the camera, consistently for NEE and sampling.
//
// The coat may have a shading normal of its own (the extension's clearcoatNormalTexture):
// `frame`, the coat's frame in the base's local frame. The coat then reflects about it as
// classic normal mapping does: f_coat, its albedo and its sampling in the coat's frame, its
// cosine the coat's (eval returns c f_coat |cos θi′| / |cos θi|, so that the caller's
// base cosine leaves the coat's), and nothing that leaves below the base's surface.
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/microfacet.h"
#include "prism/core/frame.h"

namespace prism::bsdf {

// Directional albedo of a GGX coat of unit weight and η = Clearcoat::kIor from a direction
// with |cos θ| = cos_theta, perceptual roughness r ∈ [0, 1]: the average over the visible
// normals of F(wo·h) G2 / G1(wo) (Heitz 2018, the estimator of VNDF sampling), tabulated on
// a 32 × 32 grid in (cos θ, r) by deterministic quadrature on first use and bilinearly
// interpolated. r = 0 is the Fresnel reflectance itself.
float coat_directional_albedo(float cos_theta, float perceptual_roughness);

struct Clearcoat {
  static constexpr float kIor = 1.5f;  // KHR_materials_clearcoat: the coat's IOR is 1.5

  float weight = 0.0f;  // c ∈ [0, 1]; 0: no coat
  float perceptual_roughness = 0.0f;
  MicrofacetDistribution distribution = MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.0f);
  // The coat's own shading frame in the base's local frame, or null: the base's. It points
  // at a frame the caller keeps for as long as it uses the coat: held by value, as a
  // std::optional<Frame>, it made every BSDF 40 bytes larger, coated or not, and cost the
  // Lambertian Cornell box 4 % of its render time. Size alone is not the rule: taking 96
  // bytes out of the largest lobe gained nothing (docs/performance-design.md "BSDF size"). Time every
  // new member of a BSDF, even where it is absent.
  const Frame* frame = nullptr;

  static Clearcoat make(float weight, float perceptual_roughness) {
    return {weight, perceptual_roughness,
            MicrofacetDistribution::isotropic(MicrofacetType::ggx, perceptual_roughness * perceptual_roughness),
            nullptr};
  }

  bool present() const { return weight > 0.0f; }
  // At α below the distribution's kSmoothAlpha the coat is a mirror (a delta lobe).
  bool is_smooth() const { return distribution.effectively_smooth(); }

  // c E(|cos θo|): what the coat reflects of light from wo; the base under it gets 1 − c E.
  float albedo(const Vec3f& wo) const;

  // c f_coat(wo, wi) without the cosine; 0 for a smooth coat (delta) or opposite sides.
  float eval(const Vec3f& wo, const Vec3f& wi) const;
  // Density of sample_direction(wo, ·); 0 for a smooth coat.
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  // A reflected direction on wo's side: the mirror direction for a smooth coat, else from
  // the GGX visible normals. Nothing when the reflection leaves below the surface.
  std::optional<Vec3f> sample_direction(const Vec3f& wo, Vec2f u) const;

 private:
  // c f_coat in the coat's own frame.
  float untilted_eval(const Vec3f& wo, const Vec3f& wi) const;
};

}  // namespace prism::bsdf
