#include "prism/scene/load_scene.h"

#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"
#include "prism/scene/builtin_scenes.h"

namespace prism {

Scene load_scene(std::string_view name_or_path) {
  if (is_builtin_scene(name_or_path)) return make_builtin_scene(name_or_path);
  const std::filesystem::path path(name_or_path);
  std::error_code ec;
  if (!path.has_extension() && !std::filesystem::exists(path, ec))
    return make_builtin_scene(name_or_path);  // throws UsageError naming the built-ins
  if (!std::filesystem::exists(path, ec))
    throw IoError(fmt::format("cannot read scene '{}': no such file", path.string()));
  if (std::filesystem::is_directory(path, ec))
    throw IoError(fmt::format("cannot read scene '{}': it is a directory", path.string()));
  // Scene file loaders (glTF, pbrt-v4, OBJ, Prism JSON) arrive with the loaders issue.
  throw SceneError(fmt::format("cannot read scene '{}': no loader for '{}' files yet (built-in scenes: {})",
                               path.string(), path.extension().string(), fmt::join(builtin_scene_names(), ", ")));
}

}  // namespace prism
