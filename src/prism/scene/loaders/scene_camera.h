#pragma once
// A default camera for scene files that define none (OBJ always, JSON optionally).
#include "prism/scene/scene.h"

namespace prism::loaders {

// Looks at the centre of the geometry's bounding box (instances applied) from the +z side,
// far enough that a 40° field of view holds the bounding sphere.
Camera frame_scene_camera(const Scene& scene);

}  // namespace prism::loaders
