#include "prism/scene/loaders/path_safety.h"

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism::loaders {

bool is_inside_folder(const std::filesystem::path& path, const std::filesystem::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // trailing separator of a folder path
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

std::filesystem::path resolve_scene_reference(const std::filesystem::path& scene_dir, std::string_view reference,
                                              bool allow_external_paths, std::string_view where) {
  if (reference.empty()) throw SceneError(fmt::format("{}: empty file name", where));
  if (reference.find('\0') != std::string_view::npos)
    throw SceneError(fmt::format("{}: file name contains a NUL character", where));
  if (scene_dir.empty())
    throw SceneError(fmt::format("{}: a built-in scene cannot refer to the file '{}'", where, reference));
  const std::filesystem::path written(reference);
  if (written.is_absolute() && !allow_external_paths)
    throw SceneError(fmt::format("{}: absolute path '{}' refused (scene files may only refer to files in their "
                                 "own folder; use --allow-external-paths to permit it)",
                                 where, reference));
  std::error_code ec;
  const std::filesystem::path base = std::filesystem::weakly_canonical(std::filesystem::absolute(scene_dir, ec), ec);
  if (ec) throw IoError(fmt::format("{}: cannot resolve the scene folder '{}': {}", where, scene_dir.string(), ec.message()));
  // weakly_canonical follows symbolic links of the existing prefix, so a link inside the
  // folder that points outside it is caught by the same test as a `..` path.
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(base / written, ec);
  if (ec) throw IoError(fmt::format("{}: cannot resolve '{}': {}", where, reference, ec.message()));
  if (!allow_external_paths && !is_inside_folder(resolved, base))
    throw SceneError(fmt::format("{}: path '{}' leads outside the scene's folder (refused; use "
                                 "--allow-external-paths to permit it)",
                                 where, reference));
  return resolved;
}

}  // namespace prism::loaders
