#pragma once
// Checks every loader applies to the meshes it builds, before the scene reaches the
// accelerator: a bad index or a non-finite number is an error naming where it came from;
// a zero-area triangle is dropped (it can never be hit, and it breaks area-light sampling).
#include <cstddef>
#include <string_view>

#include "prism/scene/scene.h"

namespace prism::loaders {

// Throws SceneError ("<where>: ...") for: an index count that is not a multiple of 3, an
// index past the vertices, non-finite positions/normals/uvs, or attribute arrays whose
// length differs from the positions'. Removes zero-area triangles and returns how many.
std::size_t check_and_clean_mesh(TriangleMesh& mesh, std::string_view where);

}  // namespace prism::loaders
