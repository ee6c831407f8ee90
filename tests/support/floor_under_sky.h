#pragma once
// A test scene for materials whose albedo is known: one large floor of the given material
// (a JSON material object named "floor"), seen straight down through a 1° view, under a
// uniform white sky of 1 nit, so that the floor's radiance is its directional albedo at
// normal incidence.
#include <string>

#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/scene.h"

namespace prism::test {

inline Scene floor_under_white_sky(const std::string& material) {
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [)" + material + R"(],
    "meshes": [{"name": "floor", "material": "floor",
                "positions": [[-100, 0, -100], [100, 0, -100], [100, 0, 100], [-100, 0, 100]],
                "indices": [0, 2, 1, 0, 3, 2]}],
    "camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_degrees": 1},
    "environment": {"color": [1, 1, 1], "luminance_nits": 1}})",
                                   "floor.json", {}, "floor");
}

}  // namespace prism::test
