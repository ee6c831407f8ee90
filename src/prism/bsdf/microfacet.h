#pragma once
// Microfacet normal distributions in the local shading frame (z = macro normal): GGX /
// Trowbridge–Reitz, Beckmann and Blinn-Phong, each with D(h), Smith Λ(w), G1 and the
// height-correlated G2 (Heitz 2014, "Understanding the Masking-Shadowing Function in
// Microfacet-Based BRDFs", JCGT 3(2)), classic sampling of D(h)·cos θh, and for GGX
// sampling of the visible normals D_wo(h) (Heitz 2018, JCGT 7(4); or the spherical-cap
// construction of Dupuy & Benyoub 2023).
//
// Roughness is α (the caller squares perceptual roughness). GGX and Beckmann accept
// anisotropic αx ≠ αy along the frame's x and y axes; Blinn-Phong is isotropic (αx is used)
// with exponent e = 2/α² − 2 (Walter et al. 2007, "Microfacet Models for Refraction",
// §5.2), and borrows Beckmann's Λ at the same α, which that paper recommends; that Λ is an
// approximation, so Blinn-Phong satisfies the projected-area identity only approximately.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "prism/core/vec.h"

namespace prism::bsdf {

enum class MicrofacetType : std::uint8_t { ggx, beckmann, blinn_phong };

// How sample_microfacet_normal() draws h for an outgoing direction wo. The visible-normal
// methods exist for GGX only; other distributions always use classic NDF sampling.
enum class MicrofacetSampling : std::uint8_t {
  visible_normals,  // Heitz 2018 (default)
  spherical_caps,   // Dupuy & Benyoub 2023
  ndf,              // D(h)·cos θh, ignoring wo (Walter et al. 2007 §5.3)
};

// Blinn-Phong exponent ↔ Beckmann-equivalent α (Walter et al. 2007, §5.2: e = 2α⁻² − 2).
float blinn_phong_exponent_from_alpha(float alpha);
float alpha_from_blinn_phong_exponent(float exponent);

struct MicrofacetDistribution {
  MicrofacetType type = MicrofacetType::ggx;
  float alpha_x = 0.5f;
  float alpha_y = 0.5f;
  MicrofacetSampling sampling = MicrofacetSampling::visible_normals;

  static MicrofacetDistribution isotropic(MicrofacetType t, float alpha,
                                          MicrofacetSampling s = MicrofacetSampling::visible_normals) {
    return {t, alpha, alpha, s};
  }

  // Below this α the lobe is numerically a delta: BSDFs switch to their smooth form.
  static constexpr float kSmoothAlpha = 1e-3f;
  bool effectively_smooth() const { return alpha_x < kSmoothAlpha && alpha_y < kSmoothAlpha; }

  // Normal distribution D(h) per unit solid angle of h; 0 for h.z ≤ 0. Normalised so that
  // ∫ D(h) cos θh dωh = 1.
  float D(const Vec3f& h) const;
  // Smith Λ(w): G1(w) = 1 / (1 + Λ(w)). Depends on w only through |w.z|.
  float lambda(const Vec3f& w) const;
  float G1(const Vec3f& w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated masking-shadowing (Heitz 2014, eq. 99): 1 / (1 + Λ(wo) + Λ(wi)).
  float G2(const Vec3f& wo, const Vec3f& wi) const {
    return 1.0f / (1.0f + lambda(wo) + lambda(wi));
  }
  // Height-correlated form for transmission, wo and wi on opposite sides (Heitz 2014,
  // §6.2): ∫₀¹ C^Λ(wo) (1 − C)^Λ(wi) dC = B(1 + Λ(wo), 1 + Λ(wi)), the Beta function.
  float G2_transmission(const Vec3f& wo, const Vec3f& wi) const;

  // Classic NDF sampling: h with density D(h)·cos θh, always in the upper hemisphere.
  Vec3f sample_ndf(Vec2f u) const;
  float pdf_ndf(const Vec3f& h) const { return h.z > 0.0f ? D(h) * h.z : 0.0f; }

  // Distribution of visible normals (Heitz 2014, eq. 38):
  //   D_wo(h) = G1(wo) max(0, wo·h) D(h) / wo.z.
  // A wo below the surface is treated as −wo (the microsurface seen from the other side),
  // so h is always in the upper hemisphere. GGX only.
  Vec3f sample_vndf_heitz2018(const Vec3f& wo, Vec2f u) const;
  Vec3f sample_vndf_spherical_cap(const Vec3f& wo, Vec2f u) const;
  float pdf_vndf(const Vec3f& wo, const Vec3f& h) const;

  // The strategy chosen by `sampling` (NDF for non-GGX), and its density of h.
  Vec3f sample_microfacet_normal(const Vec3f& wo, Vec2f u) const;
  float pdf_microfacet_normal(const Vec3f& wo, const Vec3f& h) const;
  bool uses_visible_normals() const {
    return type == MicrofacetType::ggx && sampling != MicrofacetSampling::ndf;
  }
};

// Anisotropy as glTF's KHR_materials_anisotropy parametrises it (render/anisotropy.h): α
// along the anisotropy direction is mix(α, 1, a²) for α across it and strength a (clamped
// to [0, 1]).
inline float anisotropic_alpha_along(float alpha_across, float strength) {
  const float a = std::clamp(strength, 0.0f, 1.0f);
  return alpha_across + (1.0f - alpha_across) * a * a;
}
// Its inverse: the strength that stretches α_across to α_along (α_across ≤ α_along ≤ 1),
// for formats that give the two α (pbrt-v4's uroughness, vroughness).
inline float anisotropy_strength_for(float alpha_across, float alpha_along) {
  if (!(alpha_across < 1.0f)) return 0.0f;
  return std::sqrt(std::clamp((alpha_along - alpha_across) / (1.0f - alpha_across), 0.0f, 1.0f));
}
// The narrowest α across the direction: an anisotropic lobe is never a delta (its α along
// the direction need not be small), and as MetallicRoughness::kMinAlpha this keeps
// D(h) ∝ 1/(α_x α_y) finite and evaluable in float.
inline constexpr float kMinAnisotropicAlpha = 2e-3f;

// Density of the reflected direction wi = reflect(wo, h) given the density of h:
// p(wi) = p(h) / (4 |wo·h|) (Walter et al. 2007, eq. 14).
inline float reflection_jacobian(const Vec3f& wo, const Vec3f& h) {
  const float d = std::abs(dot(wo, h));
  return d > 0.0f ? 1.0f / (4.0f * d) : 0.0f;
}

}  // namespace prism::bsdf
