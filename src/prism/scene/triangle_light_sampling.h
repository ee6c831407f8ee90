#pragma once
// Next-event sampling of one emissive triangle from a reference point, and the matching
// solid-angle density (MIS needs it when BSDF sampling hits the triangle).
//
// Strategies:
//   area (LightSampler's default, by measurement): a uniform point on the triangle (Osada
//     et al. 2002); p_ω = r² / (cos θ_light A). ~12 ns per sample.
//   solid_angle: a uniform direction in the triangle's solid angle (Arvo 1995); p_ω = 1/Ω.
//     Removes the r²/cos θ_light variation of area sampling, which dominates near a light.
//   solid_angle_cosine: Arvo's map preceded by a bilinear warp whose corner
//     values are |cos| between the receiver's normal and the directions to the vertices
//     (Hart et al. 2020, §5.2), so directions also follow the receiver's cosine roughly;
//     p_ω = p_bilinear(u) / Ω with u the inverse of Arvo's map. Without a receiver normal
//     (zero vector) this is solid_angle. Both cost ~140–170 ns per sample (double-precision
//     trigonometry); on the Cornell box that outweighs their variance reduction.
// As pbrt-v4 does (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., triangle
// sampling), triangles subtending less than
// kMinSolidAngleSr (area sampling is then nearly uniform in solid angle already, and
// Arvo's trigonometry loses precision) or more than kMaxSolidAngleSr (the reference is
// almost in the triangle's plane; the spherical triangle degenerates) use area sampling.
// The choice depends only on (triangle, reference), so sampling and pdf always agree.
#include <cmath>
#include <optional>

#include "prism/core/vec.h"
#include "prism/sampling/warps.h"

namespace prism {

enum class TriangleLightSampling : unsigned char { area, solid_angle, solid_angle_cosine };

inline constexpr double kMinSolidAngleSr = 3e-4;
inline constexpr double kMaxSolidAngleSr = 6.22;
inline constexpr double kMinReceiverCosineWeight = 0.01;  // keeps every direction sampleable

struct TriangleLight {
  Vec3f p0, e1, e2;  // p1 = p0 + e1, p2 = p0 + e2
  Vec3f normal;      // unit, (e1 × e2) / |e1 × e2|
  float area = 0.0f;
  bool two_sided = false;
};

struct TriangleLightSample {
  Vec3f position;
  Vec2f barycentric;  // (b1, b2): position = p0 + e1 b1 + e2 b2
  Vec3f wi;           // unit, from the reference towards position
  float distance = 0.0f;
  float pdf_sr = 0.0f;  // solid-angle density (no light selection)
};

// Nothing when the triangle cannot light the reference (faces away, degenerate).
std::optional<TriangleLightSample> sample_triangle_light(const TriangleLight& light, TriangleLightSampling strategy,
                                                         const Vec3f& reference, const Vec3f& receiver_normal,
                                                         Vec2f u);

// The area strategy alone, inline: the default's hot path (a next-event sample per
// diffuse vertex) pays no call and no strategy test.
inline std::optional<TriangleLightSample> sample_triangle_light_by_area(const TriangleLight& light,
                                                                        const Vec3f& reference, Vec2f u) {
  if (!(light.area > 0.0f)) return std::nullopt;
  TriangleLightSample s;
  s.barycentric = sample_uniform_triangle(u);
  s.position = light.p0 + light.e1 * s.barycentric.x + light.e2 * s.barycentric.y;
  const Vec3f d = s.position - reference;
  const float d2 = length_squared(d);
  if (!(d2 > 0.0f)) return std::nullopt;
  s.distance = std::sqrt(d2);
  s.wi = d / s.distance;
  float cos_light = -dot(light.normal, s.wi);
  if (light.two_sided) cos_light = std::abs(cos_light);
  if (cos_light <= 0.0f) return std::nullopt;
  s.pdf_sr = d2 / (cos_light * light.area);  // area → solid angle: p_A r² / cos θ_light
  return s;
}

// Solid-angle density with which sample_triangle_light chooses `position` (on the
// triangle); 0 where it never would.
float triangle_light_pdf(const TriangleLight& light, TriangleLightSampling strategy, const Vec3f& reference,
                         const Vec3f& receiver_normal, const Vec3f& position);

}  // namespace prism
