#pragma once
// Resolution of file references inside scene files (textures, meshes, MTL libraries), shared
// by every loader so that the folder-escape rule is enforced in exactly one place.
#include <filesystem>
#include <string_view>

namespace prism::loaders {

// Resolves `reference` as written in a scene file against `scene_dir` (the folder of the
// scene file) and returns the absolute, normalised path. Throws SceneError with `where`
// (e.g. "scene.json: materials[0].base_color_texture") when the reference is empty,
// contains a NUL, or — unless `allow_external_paths` — is absolute or leads outside
// `scene_dir` (symbolic links are followed before the check). An empty `scene_dir` means
// the scene has no folder (a built-in scene): every file reference is refused.
std::filesystem::path resolve_scene_reference(const std::filesystem::path& scene_dir, std::string_view reference,
                                              bool allow_external_paths, std::string_view where);

// True when `path` (normalised) is `folder` or lies below it.
bool is_inside_folder(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace prism::loaders
