#pragma once
// The renderer's view of a scene: flat arrays of meshes, materials and a camera.
// Loaders fill it; the accelerator and integrator only read it.
#include <cstdint>
#include <string>
#include <vector>

#include "prism/core/vec.h"

namespace prism {

struct TriangleMesh {
  std::string name;
  std::vector<Vec3f> positions;
  std::vector<std::uint32_t> indices;  // three per triangle
  std::uint32_t material = 0;

  std::size_t triangle_count() const { return indices.size() / 3; }
};

// Lambertian material with optional one-sided diffuse emission (linear RGB for now;
// spectral data arrives with the colour issue). Emission leaves the front face, the
// side the triangle's geometric normal (counter-clockwise winding) points to.
struct Material {
  std::string name;
  Vec3f albedo{0.5f};
  Vec3f emitted_radiance{0.0f};  // W·sr⁻¹·m⁻² per channel, in the film's RGB space

  bool is_emissive() const { return max_component(emitted_radiance) > 0.0f; }
};

// Pinhole camera. The field of view spans the smaller image axis.
struct Camera {
  Vec3f eye{0.0f, 0.0f, 0.0f};
  Vec3f target{0.0f, 0.0f, 1.0f};
  Vec3f up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 40.0f;
};

struct Scene {
  std::string name;
  std::vector<TriangleMesh> meshes;
  std::vector<Material> materials;
  Camera camera;
  int default_width = 512;
  int default_height = 512;

  std::size_t triangle_count() const;
};

// Throws SceneError when indices are out of range, a material index is invalid,
// positions are not finite, or the scene has no geometry.
void validate_scene(const Scene& scene);

}  // namespace prism
