#include "prism/scene/load_scene.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/loaders/embedded_scenes.h"
#include "prism/scene/loaders/gltf_scene.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/obj_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"

namespace prism {

std::vector<std::string> all_builtin_scene_names() {
  std::vector<std::string> names = builtin_scene_names();
  for (auto& n : loaders::embedded_scene_names()) names.push_back(std::move(n));
  return names;
}

namespace {

Scene load_named_or_file(std::string_view name_or_path, const LoadOptions& options) {
  if (is_builtin_scene(name_or_path)) return make_builtin_scene(name_or_path);
  if (const auto json = loaders::embedded_scene_json(name_or_path))
    return loaders::parse_json_scene(*json, fmt::format("built-in scene '{}'", name_or_path), {}, name_or_path, options);
  const std::filesystem::path path(name_or_path);
  std::error_code ec;
  if (!path.has_extension() && !std::filesystem::exists(path, ec))
    throw UsageError(fmt::format("unknown scene '{}' (built-in scenes: {})", name_or_path,
                                 fmt::join(all_builtin_scene_names(), ", ")));
  if (!std::filesystem::exists(path, ec))
    throw IoError(fmt::format("cannot read scene '{}': no such file", path.string()));
  if (std::filesystem::is_directory(path, ec))
    throw IoError(fmt::format("cannot read scene '{}': it is a directory", path.string()));
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".json") return loaders::load_json_scene(path, options);
  if (extension == ".obj") return loaders::load_obj_scene(path, options);
  if (extension == ".pbrt") return loaders::load_pbrt_scene(path, options);
  if (extension == ".gltf" || extension == ".glb") return loaders::load_gltf_scene(path, options);
  throw SceneError(fmt::format("cannot read scene '{}': no loader for '{}' files (supported: .json, .obj, .pbrt, .gltf, .glb)",
                               path.string(), path.extension().string()));
}

}  // namespace

Scene load_scene(std::string_view name_or_path, const LoadOptions& options) {
  Scene scene = load_named_or_file(name_or_path, options);
  // The glTF loader refuses a variant its file does not name; other scenes have none.
  if (!options.material_variant.empty() && scene.material_variants.empty())
    throw UsageError(fmt::format("scene '{}' has no material variants (glTF KHR_materials_variants), so no variant '{}'",
                                 name_or_path, options.material_variant));
  return scene;
}

}  // namespace prism
