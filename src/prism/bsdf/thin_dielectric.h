#pragma once
// Thin dielectric slab (a window pane, a soap film without interference): two parallel
// smooth interfaces so close together that the light leaving the slab leaves where it
// entered. Summing the geometric series of inter-reflections inside the slab (pbrt-v4,
// 4th ed., §9.5.1 "Thin Dielectric BSDF") gives, with R the single-interface Fresnel
// reflectance at the incidence angle and T = 1 − R,
//   R' = R + T² R / (1 − R²),   T' = 1 − R',
// reflected in the mirror direction and transmitted straight through (wi = −wo: the two
// refractions cancel, so the slab shifts nothing seen through it). Both lobes are deltas.
//
// Per-wavelength IOR: each channel gets its own R'(η_c); as neither direction depends on
// η, the channels share one sampled direction and dispersion does not apply (no hero
// wavelength termination, is_dispersive() is false). Transmission crosses the slab twice
// (in and out), so the radiance scaling 1/η² of each refraction cancels and eta = 1.
// Roughness is not modelled: a thin-walled dielectric is treated as smooth.
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/bsdf/fresnel.h"

namespace prism::bsdf {

// The slab's total reflectance R' for one single-interface Fresnel reflectance R.
inline float thin_slab_reflectance(float r) {
  const float t = 1.0f - r;
  return r < 1.0f ? r + t * t * r / (1.0f - r * r) : 1.0f;
}

template <int N>
struct ThinDielectric {
  color::SampledSpectrum<N> eta{1.5f};  // η_slab / η_surrounding per channel
  color::SampledSpectrum<N> transmission_tint{1.0f};  // multiplies T' (glTF: the base colour), in [0, 1]

  // R' per channel at the incidence cosine (either side: the slab is symmetric).
  color::SampledSpectrum<N> reflectance(float cos_theta) const {
    color::SampledSpectrum<N> r;
    for (int c = 0; c < N; ++c) r[c] = thin_slab_reflectance(fresnel_dielectric(std::abs(cos_theta), eta[c]));
    return r;
  }

  color::SampledSpectrum<N> eval(const Vec3f&, const Vec3f&) const { return {}; }
  float pdf(const Vec3f&, const Vec3f&) const { return 0.0f; }

  // Reflection is chosen with probability mean(R'), transmission with 1 − mean(R'); each
  // channel's f carries its own R' or T' over that probability's lobe, so every channel
  // is estimated without bias (a lobe with positive R' or T' has positive probability
  // unless all channels' values are 0 there).
  std::optional<BsdfSample<N>> sample(const Vec3f& wo, float u_lobe, Vec2f /*u*/) const {
    if (wo.z == 0.0f) return std::nullopt;
    const color::SampledSpectrum<N> r = reflectance(wo.z);
    const float p_reflect = r.average();
    BsdfSample<N> s;
    s.is_specular = true;
    const float inv_cos = 1.0f / std::abs(wo.z);
    if (u_lobe < p_reflect) {
      s.wi = Vec3f(-wo.x, -wo.y, wo.z);
      s.f = r * inv_cos;
      s.pdf = p_reflect;
    } else {
      s.wi = -wo;
      s.f = (color::SampledSpectrum<N>(1.0f) - r) * transmission_tint * inv_cos;
      s.pdf = 1.0f - p_reflect;
      s.is_transmission = true;
    }
    return s;
  }
};

}  // namespace prism::bsdf
