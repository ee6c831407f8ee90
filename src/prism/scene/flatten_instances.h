#pragma once
#include "prism/core/bounds.h"
#include "prism/scene/scene.h"

namespace prism {

// A copy of the scene in which every instance is a world-space mesh (positions and
// normals transformed) and `instances` is empty. Scenes without instances are returned
// unchanged. The integrator and light sampling then see plain triangles.
Scene flatten_instances(const Scene& scene);

// Bounds of all mesh positions (after flattening).
Bounds3f scene_bounds(const Scene& scene);

}  // namespace prism
