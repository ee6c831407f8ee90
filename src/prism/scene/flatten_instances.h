#pragma once
#include "prism/core/bounds.h"
#include "prism/scene/scene.h"

namespace prism {

// The scene with every instance made a world-space mesh (positions and normals
// transformed) and `instances` empty. Scenes without instances are returned unchanged.
// The integrator and light sampling then see plain triangles. Taken by value: pass an
// rvalue to hand the scene's meshes and texels over instead of copying them.
Scene flatten_instances(Scene scene);

// Bounds of all mesh positions (after flattening).
Bounds3f scene_bounds(const Scene& scene);

}  // namespace prism
