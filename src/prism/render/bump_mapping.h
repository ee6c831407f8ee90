#pragma once
// Bump maps (Blinn 1978, "Simulation of Wrinkled Surfaces"; the construction of pbrt-v4's
// BumpMap, Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed., §10.5.2): a
// height texture h(u, v), in scene units, displaces the surface along its shading normal,
// p' = p + h n, and the shading normal becomes the displaced surface's,
// ∂p'/∂u × ∂p'/∂v with ∂p'/∂u ≈ ∂p/∂u + (∂h/∂u) n. The term h ∂n/∂u is dropped (bump
// heights are small against the surface's radius of curvature). The integrator takes the
// height's derivatives by finite differences over the ray footprint (wavefront_integrator.cpp).
#include <cmath>

#include "prism/core/vec.h"

namespace prism {

// The bumped shading normal (unit, on n's side) for the shading normal n, the position
// derivatives dP/du, dP/dv and the height's derivatives dh/du, dh/dv (scene units per unit
// of u and v). The position derivatives are first made perpendicular to n, so that a flat
// height gives n back: with interpolated normals the base surface is the shading one.
inline Vec3f bumped_normal(const Vec3f& n, const Vec3f& dpdu, const Vec3f& dpdv, float dh_du, float dh_dv) {
  const Vec3f a = dpdu - n * dot(n, dpdu) + n * dh_du;
  const Vec3f b = dpdv - n * dot(n, dpdv) + n * dh_dv;
  const Vec3f c = cross(a, b);
  const float len = length(c);
  if (!(len > 0.0f) || !std::isfinite(len)) return n;
  // Mirrored uvs turn dP/du × dP/dv away from n: the displaced surface's normal is the one
  // on n's side either way.
  return dot(c, n) < 0.0f ? -c / len : c / len;
}

}  // namespace prism
