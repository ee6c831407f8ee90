#include "prism/scene/flatten_instances.h"

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {
namespace {

// Normals transform with the inverse transpose of the linear part (cofactor matrix; its
// scale does not matter because normals are renormalised).
Vec3f transform_normal(const Transform& t, const Vec3f& n) {
  const Vec3f r0(t.m[0][0], t.m[0][1], t.m[0][2]), r1(t.m[1][0], t.m[1][1], t.m[1][2]),
      r2(t.m[2][0], t.m[2][1], t.m[2][2]);
  const Vec3f c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
  const float det = dot(r0, c0);
  const Vec3f out = c0 * n.x + c1 * n.y + c2 * n.z;
  return det < 0.0f ? -out : out;
}

}  // namespace

Scene flatten_instances(Scene scene) {
  if (scene.instances.empty()) return scene;
  const std::vector<TriangleMesh> meshes = std::move(scene.meshes);
  const std::vector<Instance> instances = std::move(scene.instances);
  scene.meshes.clear();
  scene.instances.clear();
  for (const Instance& inst : instances) {
    if (inst.mesh >= meshes.size())
      throw SceneError(fmt::format("instance refers to mesh {} of {}", inst.mesh, meshes.size()));
    TriangleMesh mesh = meshes[inst.mesh];
    for (Vec3f& p : mesh.positions) p = inst.object_to_world.apply_point(p);
    for (Vec3f& n : mesh.normals) n = normalize(transform_normal(inst.object_to_world, n));
    for (Vec3f& t : mesh.tangents) t = normalize(inst.object_to_world.apply_vector(t));
    // A mirroring transform turns counter-clockwise into clockwise: restore the winding.
    const Transform& t = inst.object_to_world;
    const float det = t.m[0][0] * (t.m[1][1] * t.m[2][2] - t.m[1][2] * t.m[2][1]) -
                      t.m[0][1] * (t.m[1][0] * t.m[2][2] - t.m[1][2] * t.m[2][0]) +
                      t.m[0][2] * (t.m[1][0] * t.m[2][1] - t.m[1][1] * t.m[2][0]);
    if (det < 0.0f)
      for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    // ... and swaps the handedness of n × t against the mirrored bitangent.
    if (det < 0.0f && !mesh.tangents.empty()) {
      if (mesh.tangent_signs.empty()) mesh.tangent_signs.assign(mesh.tangents.size(), 1.0f);
      for (float& s : mesh.tangent_signs) s = -s;
    }
    scene.meshes.push_back(std::move(mesh));
  }
  return scene;
}

Bounds3f scene_bounds(const Scene& scene) {
  Bounds3f b;
  for (const auto& mesh : scene.meshes)
    for (const auto& p : mesh.positions) b.extend(p);
  return b;
}

}  // namespace prism
