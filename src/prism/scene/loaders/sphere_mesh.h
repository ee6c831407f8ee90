#pragma once
// Tessellated spheres for scene files that ask for a `"sphere"` shape (Prism's geometry is
// triangles only).
#include "prism/scene/scene.h"

namespace prism::loaders {

// A latitude-longitude sphere: `rings` bands from pole to pole (≥ 2) and 2·rings segments
// around, counter-clockwise seen from outside, with outward unit normals and uvs (u around
// from +x towards −z, v from the north pole (+y) to the south). The pole bands use one
// triangle per segment, so no triangle is degenerate.
TriangleMesh make_uv_sphere(const Vec3f& center, float radius, int rings);

}  // namespace prism::loaders
