#pragma once
// A stand-in for the loaders issue's `prism generate atrium` until it exists: a wavy
// height-field floor of about `triangles` triangles (a regular n × n grid of quads, two
// triangles each) under an emissive ceiling quad, with a camera looking down at it.
// Enough to measure scene build, BVH build and memory per triangle; not a furnished room.
#include <cstddef>

#include "prism/scene/scene.h"

namespace prism::bench {

Scene make_triangle_grid_scene(std::size_t triangles);

}  // namespace prism::bench
