#pragma once
// Prism's own scene format, "prism-scene/1": a JSON document with camera, materials,
// lights in physical units, meshes (inline, by OBJ file, or generated shapes), instances
// and an environment. The format is specified in docs/scene-formats.md.
#include <cstddef>
#include <filesystem>
#include <string_view>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"

namespace prism::loaders {

inline constexpr std::string_view kJsonSceneFormat = "prism-scene/1";

// Reads and parses a scene file; file references resolve against its folder.
// Missing/unreadable file: IoError. Malformed JSON: SceneError "<file>:<line>:<col>: ...".
// Schema errors: SceneError "<file>: <json path>: ...".
Scene load_json_scene(const std::filesystem::path& path, const LoadOptions& options = {});

// Parses a document held in memory. `source` names it in messages; `scene_dir` is the
// folder file references resolve against (empty: the document may not refer to files, as
// for the built-in scenes). `default_name` is the scene name when the document has none.
Scene parse_json_scene(std::string_view text, std::string_view source, const std::filesystem::path& scene_dir,
                       std::string_view default_name, const LoadOptions& options = {});

// 1-based line and column (in bytes) of the byte at `offset` in `text`.
struct TextPosition {
  std::size_t line = 1, column = 1;
};
TextPosition text_position(std::string_view text, std::size_t offset);

}  // namespace prism::loaders
