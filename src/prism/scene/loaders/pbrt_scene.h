#pragma once
// A subset of the pbrt-v4 scene format (the supported directives, parameters and their
// mapping onto Prism's materials and lights are listed in docs/scene-formats.md).
// Everything outside the subset is parsed, ignored and listed in one warning.
#include <filesystem>
#include <string_view>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"

namespace prism::loaders {

// Reads `path`; Include/Import and plymesh/texture file names resolve against its folder
// (path_safety.h). Missing file: IoError. Malformed input: SceneError "<file>:<line>: ...".
Scene load_pbrt_scene(const std::filesystem::path& path, const LoadOptions& options = {});

// Parses text held in memory; `scene_dir` empty means the text may not refer to files.
Scene parse_pbrt_scene(std::string_view text, std::string_view source, const std::filesystem::path& scene_dir,
                       const LoadOptions& options = {});

}  // namespace prism::loaders
