#pragma once
// Tangent-space normal maps (glTF 2.0 §3.9.3, "normalTexture"; the tangent frame is
// MikkTSpace's, Mikkelsen 2008, "Simulation of Wrinkled Surfaces Revisited"): a texel's
// RGB stores the perturbed normal's coordinates in the frame (tangent t along +u,
// bitangent b = sign · n × t up the image, vertex normal n) as x·½ + ½. The map's x and y
// are scaled by the material's normal scale, and the shading frame is rebuilt around the
// result, its tangent kept as close to t as Gram–Schmidt allows so that anisotropic lobes
// still follow the uv layout.
#include <cmath>

#include "prism/core/frame.h"
#include "prism/scene/scene.h"

namespace prism {

// The shading frame around a new shading normal `n` (unit), made from `frame`: its
// tangent kept as close to frame.s as Gram–Schmidt allows, so that anisotropic lobes still
// follow the uv layout. A normal at or below the geometric surface is first lifted to just
// above it (cos 0.01, 0.57°): such a normal (a map authored for another mesh, a filtered
// texel at a sharp crease, a steep bump) would otherwise send every reflected direction
// through the surface.
inline Frame frame_around_normal(const Frame& frame, Vec3f n, const Vec3f& geometric_normal) {
  constexpr float kMinCosAboveSurface = 0.01f;
  const float above = dot(n, geometric_normal);
  if (above < kMinCosAboveSurface) {
    n = n + geometric_normal * (kMinCosAboveSurface - above);
    n = n / length(n);
  }
  const Vec3f s = frame.s - n * dot(n, frame.s);
  const float length_s = length(s);
  if (!(length_s > 1e-4f)) return Frame::from_normal(n);  // the tangent lies along the new normal
  // Where n has turned nearly onto the old tangent, s is a short difference of near-equal
  // vectors and off perpendicular by its rounding over its length: the bitangent from the
  // cross product, and the tangent again from it, are perpendicular to float precision.
  const Vec3f bitangent = normalize(cross(n, s / length_s));
  return Frame{cross(bitangent, n), bitangent, n};
}

// The normal-mapped shading frame. `frame` is the unperturbed one (frame.s the tangent,
// frame.n the interpolated vertex normal), `bitangent_sign` ±1 (glTF's TANGENT.w), `rgb`
// the filtered texel in [0, 1] and `geometric_normal` the triangle's normal on frame.n's
// side. A texel that decodes to no direction (x, y, z all zero, or not finite) leaves the
// frame as it was.
inline Frame normal_mapped_frame(const Frame& frame, float bitangent_sign, const Vec3f& rgb, float normal_scale,
                                 const Vec3f& geometric_normal) {
  const Vec3f m((2.0f * rgb.x - 1.0f) * normal_scale, (2.0f * rgb.y - 1.0f) * normal_scale, 2.0f * rgb.z - 1.0f);
  const Vec3f n = frame.s * m.x + frame.t * (bitangent_sign * m.y) + frame.n * m.z;
  const float length_n = length(n);
  if (!(length_n > 0.0f) || !std::isfinite(length_n)) return frame;
  return frame_around_normal(frame, n / length_n, geometric_normal);
}

// A triangle's position derivatives dP/du and dP/dv, from its corners' positions and uvs
// (e₁ = dP/du Δu₁ + dP/dv Δv₁, e₂ likewise). False when its uv mapping is degenerate.
// `det` is Δu₁Δv₂ − Δu₂Δv₁: e₁ × e₂ = det · (dP/du × dP/dv).
inline bool triangle_position_derivatives(const TriangleMesh& mesh, std::uint32_t triangle, Vec3f& dpdu, Vec3f& dpdv,
                                          float& det) {
  const std::uint32_t* i = mesh.indices.data() + 3 * static_cast<std::size_t>(triangle);
  const Vec3f e1 = mesh.positions[i[1]] - mesh.positions[i[0]], e2 = mesh.positions[i[2]] - mesh.positions[i[0]];
  const Vec2f& uv0 = mesh.uvs[i[0]];
  const Vec2f d1(mesh.uvs[i[1]].x - uv0.x, mesh.uvs[i[1]].y - uv0.y);
  const Vec2f d2(mesh.uvs[i[2]].x - uv0.x, mesh.uvs[i[2]].y - uv0.y);
  det = d1.x * d2.y - d2.x * d1.y;
  if (!(std::abs(det) > 0.0f)) return false;
  dpdu = (e1 * d2.y - e2 * d1.y) / det;
  dpdv = (e2 * d1.x - e1 * d2.x) / det;
  const float size = length_squared(dpdu) * length_squared(dpdv);
  return size > 0.0f && std::isfinite(size);
}

// A triangle's tangent along +u and its handedness, for meshes without per-vertex
// tangents (the JSON, OBJ and pbrt-v4 loaders do not generate them): dP/du, and the sign
// that makes sign · n × dP/du point up the image (towards −v), as glTF's TANGENT.w does,
// for n the front (counter-clockwise) normal. False when the uv mapping is degenerate.
inline bool triangle_tangent(const TriangleMesh& mesh, std::uint32_t triangle, Vec3f& tangent, float& sign) {
  Vec3f dpdv;
  float det = 0.0f;
  if (!triangle_position_derivatives(mesh, triangle, tangent, dpdv, det)) return false;
  // (n × dP/du) · dP/dv = n · (dP/du × dP/dv) has the sign of det for the front normal n:
  // n × dP/du runs up the image (against +v) where det < 0, which is the unmirrored case,
  // as v points down the image.
  sign = det < 0.0f ? 1.0f : -1.0f;
  return true;
}

}  // namespace prism
