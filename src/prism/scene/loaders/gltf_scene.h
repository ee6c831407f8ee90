#pragma once
// glTF 2.0 scenes (.gltf with external or embedded buffers, and binary .glb), parsed by
// tinygltf. The mapping onto Prism's meshes, instances, materials, cameras and lights is
// documented in docs/scene-formats.md.
#include <filesystem>
#include <span>
#include <string_view>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"

namespace prism::loaders {

// Missing file: IoError. Malformed file, unsupported required extension, a uri that leaves
// the file's folder (unless options.allow_external_paths): SceneError "<file>: ...".
Scene load_gltf_scene(const std::filesystem::path& path, const LoadOptions& options = {});

// `bytes` is a .gltf (JSON) or .glb (binary, recognised by its magic) document; `scene_dir`
// is the folder uris resolve against (empty: no external files allowed).
Scene parse_gltf_scene(std::span<const unsigned char> bytes, std::string_view source,
                       const std::filesystem::path& scene_dir, const LoadOptions& options = {});

}  // namespace prism::loaders
