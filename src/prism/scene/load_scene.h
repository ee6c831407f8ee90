#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"

namespace prism {

// Resolves what a user typed: a built-in scene name, or a scene file whose extension
// picks the loader (.json: Prism JSON, .obj: Wavefront OBJ). Missing/unreadable file:
// IoError; unknown name: UsageError; malformed file: SceneError with the position.
Scene load_scene(std::string_view name_or_path, const LoadOptions& options = {});

// Every built-in scene: those made in code and the JSON scenes embedded from data/scenes/.
std::vector<std::string> all_builtin_scene_names();

}  // namespace prism
