#pragma once
// Per-vertex tangents for meshes that have normals and uvs but no tangents (glTF 2.0
// §3.7.2.1 asks readers to generate them; the idea is MikkTSpace's, Mikkelsen 2008,
// "Simulation of Wrinkled Surfaces Revisited"): each triangle's dP/du and dP/dv from its
// uv derivatives, projected onto each corner's tangent plane, normalised and weighted by
// the corner's angle, accumulated per vertex; then Gram–Schmidt against the vertex normal.
//
// Handedness (TriangleMesh::tangent_signs, glTF's TANGENT.w): +1 when n × t points up the
// image (towards −v, glTF's normal-texture +Y), −1 for mirrored uvs. Triangles of either
// handedness are accumulated apart, and a vertex shared by both (a mirror seam) takes the
// side with the larger angle weight: Prism does not split vertices as MikkTSpace does.
// Vertices no triangle with a usable uv mapping touches get an arbitrary tangent
// perpendicular to their normal (Frame::from_normal) and +1.
#include "prism/scene/scene.h"

namespace prism::loaders {

// Fills mesh.tangents and mesh.tangent_signs (one per vertex). Requires per-vertex
// normals and uvs (returns false and changes nothing otherwise).
bool generate_tangents(TriangleMesh& mesh);

}  // namespace prism::loaders
