#pragma once
// Warps from the unit square to common domains, each with its density. Every warp has a
// chi-square test in tests/sampling/.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "prism/core/branch_free.h"
#include "prism/core/vec.h"

namespace prism {

// cos(πt/4) and sin(πt/4) for t ∈ [−1, 1], i.e. angles within ±π/4, by their Taylor
// polynomials through x^10 and x^9 (x = πt/4), evaluated by Horner's rule in float. The
// first omitted terms bound the truncation error: (π/4)^12/12! < 1.2e-10 for the cosine and
// (π/4)^11/11! < 1.8e-9 for the sine, far below float's 6e-8, so the result is the float
// rounding of a few operations (tests/sampling/warps_test.cpp checks ≤ 2.5e-7 absolute
// against double std::cos/std::sin). The concentric map needs no other angles, and this
// replaces a libm sincosf call per diffuse bounce.
struct CosSin {
  float cos, sin;
};
inline CosSin cos_sin_quarter_pi(float t) {
  const float x = std::numbers::pi_v<float> / 4.0f * t;
  const float x2 = x * x;
  // 1/k! for k = 2 … 10
  constexpr float c2 = 1.0f / 2.0f, c4 = 1.0f / 24.0f, c6 = 1.0f / 720.0f, c8 = 1.0f / 40320.0f,
                  c10 = 1.0f / 3628800.0f;
  constexpr float s3 = 1.0f / 6.0f, s5 = 1.0f / 120.0f, s7 = 1.0f / 5040.0f, s9 = 1.0f / 362880.0f;
  const float c = 1.0f - x2 * (c2 - x2 * (c4 - x2 * (c6 - x2 * (c8 - x2 * c10))));
  const float s = x * (1.0f - x2 * (s3 - x2 * (s5 - x2 * (s7 - x2 * s9))));
  return {c, s};
}

// Concentric map of the square to the unit disk (Shirley & Chiu 1997): area preserving,
// low distortion, so stratification of u survives. In the wedge |a| > |b| the angle is
// (π/4)(b/a); otherwise π/2 − (π/4)(a/b), whose cosine and sine are the sine and cosine
// of (π/4)(a/b).
inline Vec2f sample_concentric_disk(Vec2f u) {
  const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  // The wedge is a coin flip per sample: masked selects (core/branch_free.h), as GCC
  // compiles `wedge ? a : b` on floats to branches. Wedge |a| > |b| is |b| < |a|.
  const float abs_a = std::abs(a), abs_b = std::abs(b);
  const float r = select_less(abs_b, abs_a, a, b);
  const CosSin cs = cos_sin_quarter_pi(select_less(abs_b, abs_a, b, a) / r);
  const float along = r * cs.cos, across = r * cs.sin;
  return {select_less(abs_b, abs_a, along, across), select_less(abs_b, abs_a, across, along)};
}

// Cosine-weighted hemisphere around +z by Malley's method (project the disk up).
inline Vec3f sample_cosine_hemisphere(Vec2f u) {
  const Vec2f d = sample_concentric_disk(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

// Solid-angle density of sample_cosine_hemisphere: cos θ / π above the surface, 0 below.
inline float cosine_hemisphere_pdf(float cos_theta) {
  return cos_theta > 0.0f ? cos_theta * std::numbers::inv_pi_v<float> : 0.0f;
}

// Uniform barycentrics on a triangle by Heitz's low-distortion map between the square and
// the triangle (E. Heitz, "A Low-Distortion Map Between Triangle and Square", 2019): the
// square is cut along its diagonal and each half sheared onto half of the triangle, so the
// map is area-preserving (Jacobian ½ on both halves) and keeps neighbouring points
// neighbours: a stratified u stays stratified on the light, which the square-root
// parameterisation (Osada et al. 2002) distorts towards one vertex. Also no square root on
// the NEE path. Returns (b1, b2); b0 = 1 - b1 - b2. Area density is 1 / area.
inline Vec2f sample_uniform_triangle(Vec2f u) {
  // Heitz's two halves: (u.x/2, u.y − u.x/2) where u.x < u.y, else (u.x − u.y/2, u.y/2).
  // Both are u less half its smaller coordinate, so no branch on which half (a coin flip
  // per sample): the halved coordinate c − c/2 = c/2 is exact by Sterbenz's lemma for
  // normal floats, so this is bit for bit the two-case form (warps_test checks it).
  const float half = 0.5f * std::min(u.x, u.y);
  return {u.x - half, u.y - half};
}

// Uniform directions in the cone of half-angle acos(cos_max) around +z.
// 1 − cos θ is sampled directly and sin θ taken from it, so narrow cones (the Sun subtends
// 0.27°: 1 − cos θmax ≈ 1e-5) keep their full angular resolution instead of the ~200
// float steps that cos θ has there.
inline Vec3f sample_uniform_cone(Vec2f u, float cos_max) {
  const float one_minus_cos = u.x * (1.0f - cos_max);
  const float cos_theta = 1.0f - one_minus_cos;
  const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
  const float phi = 2.0f * std::numbers::pi_v<float> * u.y;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Solid-angle density of sample_uniform_cone: 1 / (2π (1 − cos θmax)).
inline float uniform_cone_pdf(float cos_max) {
  return 1.0f / (2.0f * std::numbers::pi_v<float> * (1.0f - cos_max));
}

// Uniform direction on the unit sphere: z uniform in [−1, 1] (Archimedes' hat-box
// theorem), φ uniform. Density 1/(4π).
inline Vec3f sample_uniform_sphere(Vec2f u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * std::numbers::pi_v<float> * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniform_sphere_pdf() { return 0.25f * std::numbers::inv_pi_v<float>; }

// Power heuristic with β = 2 (Veach 1997, eq. 9.13) for one sample from each technique.
inline float power_heuristic(float pdf_a, float pdf_b) {
  const float a2 = pdf_a * pdf_a, b2 = pdf_b * pdf_b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

}  // namespace prism
