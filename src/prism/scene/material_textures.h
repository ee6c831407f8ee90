#pragma once
// Which textures the materials look up, filtered through mip pyramids: base colour,
// metallic-roughness, normal, bump and emission textures. The others (environment maps)
// are read texel by texel, and need no pyramid.
#include <vector>

#include "prism/scene/scene.h"

namespace prism {

// One flag per Scene::textures entry: true where a material refers to it.
std::vector<bool> textures_used_by_materials(const Scene& scene);

}  // namespace prism
