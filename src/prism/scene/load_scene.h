#pragma once
#include <string_view>

#include "prism/scene/scene.h"

namespace prism {

// Resolves what a user typed: a built-in scene name, or a scene file whose extension
// picks the loader. Missing/unreadable file: IoError; unknown name: UsageError;
// malformed file: SceneError with the position.
Scene load_scene(std::string_view name_or_path);

}  // namespace prism
