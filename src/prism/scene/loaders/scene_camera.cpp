#include "prism/scene/loaders/scene_camera.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace prism::loaders {

Camera frame_scene_camera(const Scene& scene) {
  Vec3f lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  const auto extend = [&](const TriangleMesh& mesh, const Transform& t) {
    for (const Vec3f& p : mesh.positions) {
      const Vec3f q = t.apply_point(p);
      lo = min(lo, q);
      hi = max(hi, q);
    }
  };
  if (scene.instances.empty()) {
    for (const auto& mesh : scene.meshes) extend(mesh, Transform{});
  } else {
    for (const auto& instance : scene.instances)
      if (instance.mesh < scene.meshes.size()) extend(scene.meshes[instance.mesh], instance.object_to_world);
  }
  Camera camera;
  camera.name = "default";
  camera.fov_degrees = 40.0f;
  if (!(lo.x <= hi.x)) return camera;  // no geometry: validation reports it
  const Vec3f center = (lo + hi) * 0.5f;
  const float radius = std::max(0.5f * length(hi - lo), 1e-3f);
  const float half_fov = 0.5f * camera.fov_degrees * std::numbers::pi_v<float> / 180.0f;
  const float distance = radius / std::sin(half_fov);
  camera.eye = center + Vec3f(0.0f, 0.0f, distance);
  camera.target = center;
  camera.up = Vec3f(0.0f, 1.0f, 0.0f);
  camera.focus_distance = distance;
  return camera;
}

}  // namespace prism::loaders
