#pragma once
// Fresnel reflectance: Schlick's approximation from F0, the exact dielectric formula for
// a real relative IOR (with total internal reflection, light arriving from either side),
// and the conductor formula for a complex IOR η + ik. Scalar functions take one channel;
// the spectral templates apply them per channel of a SampledSpectrum<N>.
#include "prism/color/sampled_spectrum.h"

namespace prism::bsdf {

// Schlick 1994: F = F0 + (1 − F0)(1 − cos θ)⁵, cos θ taken as |cos θ|.
float fresnel_schlick(float f0, float cos_theta);

// Unpolarised reflectance of a smooth interface between two dielectrics (Born & Wolf §1.5,
// eqs. 21a/21b averaged). `eta` = η_inside / η_outside, where "outside" is the side the
// normal points to. cos_theta_i = cos of the incident direction with that normal: ≥ 0 for
// light arriving from outside, < 0 from inside (η is then inverted). Returns 1 under total
// internal reflection.
float fresnel_dielectric(float cos_theta_i, float eta);

// Cosine of the refracted direction's angle for the same convention (always ≥ 0), or a
// negative value under total internal reflection.
float refracted_cos_theta(float cos_theta_i, float eta);

// Reflectance of a conductor with complex relative IOR η + ik, light from the outside
// (|cos θ| is used). k = 0 reduces to fresnel_dielectric (Born & Wolf §14.2; evaluated with
// complex arithmetic in the dielectric formulas, which hold for complex η).
float fresnel_conductor(float cos_theta_i, float eta, float k);

template <int N>
color::SampledSpectrum<N> fresnel_schlick(const color::SampledSpectrum<N>& f0, float cos_theta) {
  color::SampledSpectrum<N> f;
  for (int i = 0; i < N; ++i) f[i] = fresnel_schlick(f0[i], cos_theta);
  return f;
}

template <int N>
color::SampledSpectrum<N> fresnel_dielectric(float cos_theta_i, const color::SampledSpectrum<N>& eta) {
  color::SampledSpectrum<N> f;
  for (int i = 0; i < N; ++i) f[i] = fresnel_dielectric(cos_theta_i, eta[i]);
  return f;
}

template <int N>
color::SampledSpectrum<N> fresnel_conductor(float cos_theta_i, const color::SampledSpectrum<N>& eta,
                                            const color::SampledSpectrum<N>& k) {
  color::SampledSpectrum<N> f;
  for (int i = 0; i < N; ++i) f[i] = fresnel_conductor(cos_theta_i, eta[i], k[i]);
  return f;
}

}  // namespace prism::bsdf
