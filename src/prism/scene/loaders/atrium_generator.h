#pragma once
// `prism generate atrium`: a deterministic, Sponza-like test scene built in code — a
// courtyard with two storeys of columns and arches around it, a floor of procedurally
// textured tiles, outer walls of textured stone blocks, a gallery floor, a gold sphere and
// a glass block, four planters with alpha-masked foliage cards (crossed quads, leaf
// texture, alpha_mode mask, cutoff 0.5), an area light overhead and a sky environment —
// whose size is set by the tessellation of the columns and arches. Textures:
// atrium_textures.h (floor, walls, leaves; scene.textures in that order).
#include <cstddef>

#include "prism/scene/scene.h"

namespace prism::loaders {

inline constexpr std::size_t kAtriumMinTriangles = 10'000;
inline constexpr std::size_t kAtriumMaxTriangles = 200'000'000;

// About `target_triangles` triangles (within a few percent above 100 k; never fewer than
// the fixed architecture needs). Units are metres. The same target gives the same scene.
// Throws UsageError outside [kAtriumMinTriangles, kAtriumMaxTriangles].
Scene generate_atrium(std::size_t target_triangles);

}  // namespace prism::loaders
