#pragma once
// Vocabulary shared by every BSDF: the sample record, the transport mode, and local-frame
// geometry (z = shading normal, the side it points to is "outside").
//
// Conventions the integrator relies on (also in docs of issue 4):
//  - Directions wo (towards the viewer / previous vertex) and wi (sampled, towards the
//    light / next vertex) both point away from the surface, in the local frame.
//  - f is the BSDF value WITHOUT the cosine: the path throughput update is
//        β ← β · f · |cos θi| / pdf       (cos θi = wi.z).
//  - Delta (specular) lobes: eval() and pdf() return 0 for them; sample() returns
//    f = (Fresnel weight) / |cos θi| and pdf = the discrete probability of picking that
//    lobe, so the same update applies. `is_specular` tells the integrator to skip NEE and
//    MIS at this bounce (use weight 1 for emission found by the continuation ray).
//  - pdf is a solid-angle density over wi (or a discrete probability for delta lobes).
#include <cmath>
#include <cstdint>
#include <optional>

#include "prism/color/sampled_spectrum.h"
#include "prism/core/vec.h"

namespace prism::bsdf {

// What the path carries: radiance from lights (camera paths; the default) or importance
// from the camera (light paths). Only refraction differs: radiance is scaled by
// (η_o/η_i)² when it crosses an interface into wo's medium, importance is not (Veach 1997,
// §5.2; the adjoint BSDF f*(wo, wi) = f(wi, wo)).
enum class TransportMode : std::uint8_t { radiance, importance };

template <int N>
struct BsdfSample {
  Vec3f wi;                    // sampled direction, local frame, unit length
  color::SampledSpectrum<N> f; // BSDF value, cosine not included
  float pdf = 0.0f;            // solid-angle density, or lobe probability if is_specular
  bool is_specular = false;    // delta lobe: skip NEE/MIS
  bool is_transmission = false;
  // The N channels had different IORs: wi, f and pdf are valid for channel 0 (the hero
  // wavelength) only, and f is 0 in the other channels. See Dielectric for what the
  // integrator must do.
  bool dispersive = false;
  // Relative IOR η_i/η_o across the interface in the sampled direction (the medium wi
  // points into over the medium wo points into); 1 for reflection. A radiance path's
  // throughput picks up 1/eta² on refraction; integrators that Russian-roulette on
  // throughput can multiply eta² back for the RR decision (pbrt-v4 §14.1.4 practice).
  float eta = 1.0f;
};

// Local-frame helpers.
inline float cos_theta(const Vec3f& w) { return w.z; }
inline float abs_cos_theta(const Vec3f& w) { return std::abs(w.z); }
inline bool same_hemisphere(const Vec3f& a, const Vec3f& b) { return a.z * b.z > 0.0f; }
// Mirror across the plane z = 0, used to evaluate two-sided reflection lobes with both
// directions in the upper hemisphere.
inline Vec3f flip_z(const Vec3f& w) { return {w.x, w.y, -w.z}; }

// A two-sided reflection lobe's directions mirrored into the upper hemisphere (when wo is
// below) and their half vector h = normalize(o + i); nothing when wo and wi lie on
// opposite sides (or either on the horizon).
struct UpperReflection {
  Vec3f o, i, h;
};
inline std::optional<UpperReflection> upper_reflection(const Vec3f& wo, const Vec3f& wi) {
  if (!same_hemisphere(wo, wi)) return std::nullopt;
  const Vec3f o = wo.z < 0.0f ? flip_z(wo) : wo, i = wo.z < 0.0f ? flip_z(wi) : wi;
  return UpperReflection{o, i, normalize(o + i)};  // o.z + i.z > 0: never the zero vector
}

// Mirror reflection of wo about the unit normal n: 2 (wo·n) n − wo.
inline Vec3f reflect(const Vec3f& wo, const Vec3f& n) { return n * (2.0f * dot(wo, n)) - wo; }

// Refraction of wo through an interface with unit normal n (pointing outside) and
// relative IOR eta = η_inside / η_outside. wo may lie on either side of n. Returns false
// under total internal reflection. Snell's law in vector form (Walter et al. 2007, eq. 40).
inline bool refract(const Vec3f& wo, Vec3f n, float eta, Vec3f& wt) {
  float cos_i = dot(wo, n);
  if (cos_i < 0.0f) {
    eta = 1.0f / eta;
    cos_i = -cos_i;
    n = -n;
  }
  const float sin2_t = std::max(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return false;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  wt = -wo / eta + n * (cos_i / eta - cos_t);
  return true;
}

}  // namespace prism::bsdf
