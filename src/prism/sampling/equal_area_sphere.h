#pragma once
// Equal-area octahedral map between the unit square and the unit sphere (Clarberg 2008,
// "Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD", JGT 13(3); pbrt-v4 book
// §3.8.3 "Equal-Area Mapping"). The square [0,1]² is folded as an octahedron: its centre is
// +z, its four corners −z, the inscribed diamond |2u−1| + |2v−1| ≤ 1 the upper hemisphere;
// the sign of x follows 2u − 1 and the sign of y follows 2v − 1 (pbrt-v4's convention, so
// its environment images read the same). Every region of the square maps to a region of
// the sphere with 4π times its area: the density of a point uniform on the square is
// 1/(4π) per steradian everywhere.
#include "prism/core/vec.h"

namespace prism {

// p ∈ [0,1]² → unit direction.
Vec3f equal_area_square_to_sphere(Vec2f p);

// Inverse of equal_area_square_to_sphere: any non-zero direction → [0,1]² (it need not
// be normalised).
Vec2f equal_area_sphere_to_square(const Vec3f& direction);

}  // namespace prism
