#pragma once
// `--camera NAME|INDEX`: choose which of a scene file's cameras renders (glTF and others
// may define several; the loaders choose the first).
#include <string_view>

#include "prism/scene/scene.h"

namespace prism {

// Sets scene.camera to the camera in scene.cameras named `spec`, or, when `spec` is a
// non-negative decimal number that no camera is named, to the camera at that zero-based
// index. Throws UsageError naming the cameras the scene has when nothing matches.
void select_camera(Scene& scene, std::string_view spec);

}  // namespace prism
