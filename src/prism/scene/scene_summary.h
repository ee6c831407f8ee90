#pragma once
// What `prism info SCENE` reports about a loaded scene.
#include <cstddef>
#include <map>
#include <string>

#include "prism/scene/scene.h"

namespace prism {

struct SceneSummary {
  std::size_t triangles = 0;          // in the meshes as stored (before instancing)
  std::size_t placed_triangles = 0;   // after instancing
  std::size_t meshes = 0, instances = 0, cameras = 0, textures = 0;
  std::size_t texture_bytes = 0;
  std::size_t emissive_materials = 0;
  std::size_t alpha_tested_materials = 0;  // alpha mask/blend that can let rays through (surface_alpha.h)
  std::size_t normal_mapped_materials = 0, bump_mapped_materials = 0;
  std::size_t absorbing_materials = 0;  // solid glass with attenuation (Material::absorbs_inside)
  std::size_t coated_materials = 0;     // with a clear coat (Material::has_clearcoat)
  std::size_t sheened_materials = 0;    // with a sheen (Material::has_sheen)
  std::size_t iridescent_materials = 0; // with a thin film (Material::has_iridescence)
  std::size_t anisotropic_materials = 0; // with anisotropic roughness (Material::has_anisotropy)
  std::size_t wide_gamut_materials = 0;  // base colour in ACEScg or Rec.2020 primaries
  std::size_t spectral_materials = 0;  // with a reflectance or emission spectrum given as data
  std::size_t spectral_lights = 0;
  std::map<std::string, std::size_t> materials_by_type;  // "diffuse" → count
  std::map<std::string, std::size_t> lights_by_type;     // "point" → count
};

SceneSummary summarize_scene(const Scene& scene);
std::string_view material_type_name(MaterialType type);
std::string_view light_type_name(LightType type);

// Multi-line, human-readable report ending in a newline: counts, textures with their
// size and memory, cameras, and every loader warning.
std::string format_scene_summary(const Scene& scene);

}  // namespace prism
