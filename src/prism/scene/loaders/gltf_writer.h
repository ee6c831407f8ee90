#pragma once
// Writing a Scene as a binary glTF 2.0 file (.glb), for generated scenes (`prism generate`).
// Meshes are written inline (uint32 indices, normals and uvs when present); materials as
// PBR metallic-roughness (diffuse: metallic 0 with KHR_materials_specular factor 0, i.e.
// Lambert; conductors: metallic 1 with the colour of the metal's spectral F0,
// bsdf/conductor_color.h; dielectrics:
// KHR_materials_transmission + KHR_materials_ior; emission with
// KHR_materials_emissive_strength; alphaMode MASK/BLEND with alphaCutoff, double-sided);
// textures as PNG images embedded in the binary chunk (texture_png.h) with a sampler each
// (wrap modes; KHR_texture_transform when a texture has a uv transform); the camera as a
// perspective camera node. Instances, punctual lights and the environment are not written
// (the environment has no glTF equivalent): UsageError for the first two, and for spectra
// given as data (scene/spectral_inputs.h).
#include <filesystem>

#include "prism/scene/scene.h"

namespace prism::loaders {

void write_scene_glb(const Scene& scene, const std::filesystem::path& path);

}  // namespace prism::loaders
