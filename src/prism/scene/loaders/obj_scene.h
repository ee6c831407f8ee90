#pragma once
// Wavefront OBJ with MTL materials (parsed by tinyobjloader). Polygons are triangulated;
// each (group, material) pair becomes one TriangleMesh with per-vertex normals and uvs
// where the file gives them. The MTL → Material mapping is in mtl_material.h.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "prism/scene/load_options.h"
#include "prism/scene/loaders/texture_cache.h"
#include "prism/scene/scene.h"

namespace prism::loaders {

struct ObjContext {
  std::filesystem::path dir;  // folder mtllib and texture names resolve against (empty: no files)
  LoadOptions options;
  TextureCache* textures = nullptr;    // where map_Kd / map_Ke go (null: ignored with a warning)
  const std::string* mtl_text = nullptr;  // when set, every mtllib reads this text instead (fuzzing)
};

// Appends the OBJ's meshes (and, without `material_override`, its MTL materials plus a
// default grey one for faces without a material) to `scene`; returns the indices of the
// meshes added. Warnings go to scene.warnings. Throws SceneError "<source>: ..." for
// malformed input (bad indices, non-finite numbers) and path violations.
std::vector<std::uint32_t> append_obj(Scene& scene, std::string_view obj_text, std::string_view source,
                                      const ObjContext& context, std::optional<std::uint32_t> material_override = {});

// `prism render model.obj`: the OBJ alone, with a camera that frames it.
Scene load_obj_scene(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace prism::loaders
