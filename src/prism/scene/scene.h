#pragma once
// The renderer's view of a scene: flat arrays of meshes, materials and a camera.
// Loaders fill it; the accelerator and integrator only read it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "prism/bsdf/normal_mapping_model.h"
#include "prism/core/transform.h"
#include "prism/core/vec.h"
#include "prism/scene/light.h"
#include "prism/scene/material.h"
#include "prism/scene/texture.h"

namespace prism {

struct TriangleMesh {
  std::string name;
  std::vector<Vec3f> positions;
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise = front
  std::vector<Vec3f> normals;          // optional per-vertex shading normals (empty: flat)
  std::vector<Vec2f> uvs;              // optional per-vertex texture coordinates
  std::vector<Vec3f> tangents;         // optional per-vertex tangents along +u (shading frame, normal mapping)
  std::vector<float> tangent_signs;    // with tangents, optional (empty: all +1): ±1, bitangent = sign · n × t (glTF TANGENT.w)
  std::uint32_t material = 0;

  std::size_t triangle_count() const { return indices.size() / 3; }
};

// A placement of a mesh. A scene without instances places every mesh once, untransformed.
struct Instance {
  std::uint32_t mesh = 0;
  Transform object_to_world;
};

// Pinhole (aperture_radius 0) or thin-lens camera. The field of view spans the smaller
// image axis. Physical exposure settings, when given, define the EV100 the display
// pipeline uses: EV100 = log2(N² / t · 100 / S).
struct Camera {
  Vec3f eye{0.0f, 0.0f, 0.0f};
  Vec3f target{0.0f, 0.0f, 1.0f};
  Vec3f up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 40.0f;
  float aperture_radius = 0.0f;  // scene units; 0 = pinhole
  float focus_distance = 1.0f;   // scene units, along the viewing direction
  float f_number = 0.0f;         // 0: no physical exposure given
  float shutter_seconds = 0.0f;
  float iso = 100.0f;
  std::string name;
};

struct Scene {
  std::string name;
  std::vector<TriangleMesh> meshes;
  std::vector<Instance> instances;  // empty: every mesh once, untransformed
  std::vector<Material> materials;
  std::vector<Light> lights;        // non-geometric lights (point, spot, directional, environment)
  std::vector<TextureImage> textures;
  Camera camera;
  std::vector<Camera> cameras;      // all cameras a file defines (camera is the chosen one)
  int default_width = 512;
  int default_height = 512;
  int default_spp = 0;        // 0: the renderer's default (files like pbrt-v4 may set it)
  // Scattering events; 0: emitted light only (pbrt-v4's maxdepth 0). None: the renderer's default.
  std::optional<int> default_max_depth;
  std::optional<NormalMapping> default_normal_mapping;  // none: the renderer's default (classic)
  // Names of the material variants the file defines (glTF KHR_materials_variants), in its
  // order; LoadOptions::material_variant picks one.
  std::vector<std::string> material_variants;
  // The image file the scene file names for its render (pbrt-v4's Film "filename"), as
  // written; empty: none. Not part of the image: `prism render` writes it when no -o is given.
  std::string output_file;
  std::vector<std::string> warnings;  // loader warnings (unsupported features), one line each

  std::size_t triangle_count() const;
};

// The map of the scene's environment: the first environment light's texture (the light
// sampler lights the scene with the first environment only), or null for none or a
// constant sky. Its texel_space is the space its texels' radiance is in.
const TextureImage* environment_map(const Scene& scene);

// Throws SceneError when indices are out of range, a material index is invalid,
// positions are not finite, the scene has no geometry, a spectrum is malformed
// (validate_spectrum) or an environment light has one.
void validate_scene(const Scene& scene);
// Throws SceneError when a material's colours or emission are not finite (or negative).
void validate_material(const Material& material);
// A spectrum given as data: the rules of spectrum_table_checks.h, `max_value` 1 for
// reflectances and kNoSpectrumMaximum for emitters. SceneError naming `owner` otherwise.
void validate_spectrum(const color::PiecewiseLinearSpectrum& spectrum, std::string_view owner, double max_value);

}  // namespace prism
