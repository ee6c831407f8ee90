#pragma once
// Uniform sampling of the solid angle a triangle subtends (Arvo 1995, "Stratified Sampling
// of Spherical Triangles", SIGGRAPH '95, Fig. 2), and the inverse map from a direction back
// to the unit square, which a density that is not uniform in the square (the bilinear
// warp of bilinear_warp.h) needs to evaluate its pdf for a given direction.
//
// Arvo's map is area preserving: u.x chooses the sub-triangle (A, B, Ĉ) of area u.x·Ω
// (Ĉ on the arc AC), u.y the point on the arc from B to Ĉ with 1 − cos(B, P) linear in
// u.y. So a stratified u gives stratified directions, and the density is 1/Ω everywhere.
// The corners of the square map to: (0,0) and (1,0) → B, (0,1) → A, (1,1) → C.
//
// Everything is computed in double: small triangles (Ω ~ 1e-4 sr) lose most of their
// float precision in the angle sums and in 1 − cos.
#include "prism/core/vec.h"

namespace prism {

using Vec2d = Vec2<double>;

struct SphericalTriangle {
  Vec3d a, b, c;               // unit directions from the centre to the three vertices
  double solid_angle_sr = 0.0;  // spherical excess Ω
  double cos_alpha = 1.0, sin_alpha = 0.0;  // of the interior angle α at a
};

// The triangle (p0, p1, p2) as seen from `centre`. Degenerate (collinear, or the centre in
// the triangle's plane) triangles have solid_angle_sr 0.
SphericalTriangle make_spherical_triangle(const Vec3d& centre, const Vec3d& p0, const Vec3d& p1, const Vec3d& p2);

// Solid angle of the spherical triangle with unit vertices a, b, c (Van Oosterom and
// Strackee 1983: tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a)); accurate for tiny ones.
double spherical_triangle_solid_angle(const Vec3d& a, const Vec3d& b, const Vec3d& c);

// Arvo's map: u ∈ [0,1)² → unit direction inside the triangle, density 1/Ω.
Vec3d sample_spherical_triangle(const SphericalTriangle& t, Vec2d u);

// The u that sample_spherical_triangle maps to the direction `w` (unit, inside the
// triangle); clamped to [0,1]².
Vec2d invert_spherical_triangle_sample(const SphericalTriangle& t, const Vec3d& w);

}  // namespace prism
