#include "prism/scene/scene.h"

#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.triangle_count();
  return n;
}

void validate_scene(const Scene& scene) {
  if (scene.meshes.empty() || scene.triangle_count() == 0)
    throw SceneError(fmt::format("scene '{}' has no triangles", scene.name));
  for (const auto& mesh : scene.meshes) {
    if (mesh.indices.size() % 3 != 0)
      throw SceneError(fmt::format("mesh '{}': index count {} is not a multiple of 3", mesh.name,
                                   mesh.indices.size()));
    if (mesh.material >= scene.materials.size())
      throw SceneError(fmt::format("mesh '{}': material index {} out of range", mesh.name, mesh.material));
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
      if (mesh.indices[i] >= mesh.positions.size())
        throw SceneError(fmt::format("mesh '{}': index {} at position {} out of range (vertices: {})",
                                     mesh.name, mesh.indices[i], i, mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      if (!is_finite(mesh.positions[i]))
        throw SceneError(fmt::format("mesh '{}': vertex {} is not finite", mesh.name, i));
  }
  for (const auto& m : scene.materials) validate_material(m);
}

void validate_material(const Material& m) {
  if (!is_finite(m.base_color) || !is_finite(m.emission.color) || !std::isfinite(m.emission.luminance_nits) ||
      m.emission.luminance_nits < 0.0f)
    throw SceneError(fmt::format("material '{}' has non-finite values", m.name));
}

}  // namespace prism
