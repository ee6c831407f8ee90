#pragma once
// Geometry at a ray hit, as the shading stage needs it.
#include <algorithm>
#include <cmath>

#include "prism/accel/embree_accel.h"
#include "prism/core/frame.h"
#include "prism/scene/scene.h"

namespace prism {

struct SurfaceInteraction {
  Vec3f position;
  Vec3f geometric_normal;  // unit front-face normal (counter-clockwise winding), not flipped
  Frame shading;           // around the shading normal, on the geometric normal's side
  Vec2f uv;
  std::uint32_t material = 0;
  std::uint32_t mesh = 0;
  std::uint32_t triangle = 0;
  // shading.s is the mesh's interpolated tangent (not an arbitrary one), and the sign of
  // its bitangent (glTF's TANGENT.w: the map's +Y is bitangent_sign · n × s).
  bool tangent_from_mesh = false;
  float bitangent_sign = 1.0f;
  float uv_area = 0.0f, world_area = 0.0f;  // of the hit triangle (texture LOD)
  bool front_face = true;        // the ray hit the counter-clockwise (front) side
  float cos_wo_geometric = 0.0f; // cos between the unflipped front normal and -ray.direction
};

inline SurfaceInteraction surface_interaction(const Scene& scene, const Hit& hit, const Ray& ray) {
  const TriangleMesh& mesh = scene.meshes[hit.mesh];
  const std::uint32_t i0 = mesh.indices[3 * hit.triangle], i1 = mesh.indices[3 * hit.triangle + 1],
                      i2 = mesh.indices[3 * hit.triangle + 2];
  const Vec3f& p0 = mesh.positions[i0];
  const Vec3f& p1 = mesh.positions[i1];
  const Vec3f& p2 = mesh.positions[i2];
  const float b0 = 1.0f - hit.u - hit.v;
  SurfaceInteraction si;
  si.material = mesh.material;
  si.mesh = hit.mesh;
  si.triangle = hit.triangle;
  // Position from barycentrics rather than origin + t·direction: it lies on the plane to
  // float precision, which keeps the self-intersection offset small.
  si.position = p0 * b0 + p1 * hit.u + p2 * hit.v;
  const Vec3f cross_p = cross(p1 - p0, p2 - p0);
  si.world_area = 0.5f * length(cross_p);
  const Vec3f ng = cross_p / (2.0f * si.world_area);
  si.cos_wo_geometric = -dot(ng, ray.direction);
  si.front_face = si.cos_wo_geometric > 0.0f;
  // Frames keep the mesh's orientation: dielectrics tell inside from outside by it, and
  // the reflection BSDFs are two-sided.
  si.geometric_normal = ng;
  Vec3f ns = ng;
  if (!mesh.normals.empty()) {
    const Vec3f n = mesh.normals[i0] * b0 + mesh.normals[i1] * hit.u + mesh.normals[i2] * hit.v;
    const float len = length(n);
    if (len > 0.0f) {
      ns = n / len;
      if (dot(ns, si.geometric_normal) < 0.0f) ns = -ns;  // same side as the geometric normal
    }
  }
  si.shading = Frame::from_normal(ns);
  if (!mesh.tangents.empty()) {
    // Per-vertex tangents (the file's, or generated along +u by the glTF loader) fix the
    // frame's turn about the normal, so it follows the surface's uv layout instead of the
    // normal's direction (what anisotropic lobes need); Gram–Schmidt against ns. The
    // frame stays right-handed: the BSDFs are symmetric under a flip of the bitangent.
    const Vec3f t = mesh.tangents[i0] * b0 + mesh.tangents[i1] * hit.u + mesh.tangents[i2] * hit.v;
    if (const auto frame = Frame::from_normal_and_tangent(ns, t)) {
      si.shading = *frame;
      si.tangent_from_mesh = true;
      if (!mesh.tangent_signs.empty()) {
        const std::vector<float>& w = mesh.tangent_signs;  // ±1 per vertex, equal across a triangle but at seams
        si.bitangent_sign = w[i0] * b0 + w[i1] * hit.u + w[i2] * hit.v < 0.0f ? -1.0f : 1.0f;
      }
    }
  }
  if (!mesh.uvs.empty()) {
    const Vec2f& t0 = mesh.uvs[i0];
    const Vec2f& t1 = mesh.uvs[i1];
    const Vec2f& t2 = mesh.uvs[i2];
    si.uv = Vec2f(t0.x * b0 + t1.x * hit.u + t2.x * hit.v, t0.y * b0 + t1.y * hit.u + t2.y * hit.v);
    si.uv_area = 0.5f * std::abs((t1.x - t0.x) * (t2.y - t0.y) - (t2.x - t0.x) * (t1.y - t0.y));
  }
  return si;
}

// Software prefetches for the shading stage, which reads each hit's index triple and then
// up to four vertex attributes of its three vertices: in a large mesh each of those is a
// cache miss, taken one path after the other. Shading slot i first asks for the index
// triple of a hit a few slots ahead, then for the vertex attributes of a nearer one,
// whose indices that earlier request has brought in. Hints only: no result depends on them.
inline void prefetch_hit_indices(const Scene& scene, const Hit& hit) {
  __builtin_prefetch(scene.meshes[hit.mesh].indices.data() + 3 * static_cast<std::size_t>(hit.triangle));
}

inline void prefetch_hit_vertices(const Scene& scene, const Hit& hit) {
  const TriangleMesh& mesh = scene.meshes[hit.mesh];
  const std::uint32_t* index = mesh.indices.data() + 3 * static_cast<std::size_t>(hit.triangle);
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t v = index[k];
    __builtin_prefetch(mesh.positions.data() + v);
    if (!mesh.normals.empty()) __builtin_prefetch(mesh.normals.data() + v);
    if (!mesh.uvs.empty()) __builtin_prefetch(mesh.uvs.data() + v);
    if (!mesh.tangents.empty()) __builtin_prefetch(mesh.tangents.data() + v);
  }
}

// Offsets a ray origin off the surface, to the side of `n` that `direction` leaves
// towards, scaled to the coordinates' magnitude so it stays above float rounding (about
// 2^-23 relative) at any scene scale. Always inlined: shade calls it up to three times per
// vertex, and GCC's out-of-line copy passed its nine floats through the stack.
[[gnu::always_inline]] inline Vec3f offset_ray_origin(const Vec3f& p, const Vec3f& n, const Vec3f& direction) {
  // Pairwise max, not std::max({…}): the initializer-list form is a loop over memory.
  const float magnitude = std::max(std::max(std::abs(p.x), std::abs(p.y)), std::max(std::abs(p.z), 1.0f));
  return p + (dot(direction, n) >= 0.0f ? n : -n) * (magnitude * 1e-5f);
}

}  // namespace prism
