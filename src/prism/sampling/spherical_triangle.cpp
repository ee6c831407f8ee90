#include "prism/sampling/spherical_triangle.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Arvo's [x | y]: the unit vector along the part of x orthogonal to the unit vector y.
// Zero when x is parallel to y.
Vec3d orthonormal_component(const Vec3d& x, const Vec3d& y) {
  const Vec3d r = x - y * dot(x, y);
  const double len = length(r);
  return len > 0.0 ? r / len : Vec3d(0.0);
}

// 1 − x·y for unit vectors, as |x − y|² / 2: no cancellation when x ≈ y.
double one_minus_dot(const Vec3d& x, const Vec3d& y) { return 0.5 * length_squared(x - y); }

}  // namespace

double spherical_triangle_solid_angle(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const double triple = std::abs(dot(a, cross(b, c)));
  const double denominator = 1.0 + dot(a, b) + dot(b, c) + dot(c, a);
  return 2.0 * std::atan2(triple, denominator);
}

SphericalTriangle make_spherical_triangle(const Vec3d& centre, const Vec3d& p0, const Vec3d& p1, const Vec3d& p2) {
  SphericalTriangle t;
  const Vec3d d0 = p0 - centre, d1 = p1 - centre, d2 = p2 - centre;
  const double l0 = length(d0), l1 = length(d1), l2 = length(d2);
  if (!(l0 > 0.0 && l1 > 0.0 && l2 > 0.0)) return t;
  t.a = d0 / l0;
  t.b = d1 / l1;
  t.c = d2 / l2;
  // Interior angle at a: between the planes through (a, b) and (a, c).
  const Vec3d n_ab = cross(t.a, t.b), n_ac = cross(t.a, t.c);
  const double sin_scaled = length(cross(n_ab, n_ac)), cos_scaled = dot(n_ab, n_ac);
  if (!(sin_scaled > 0.0)) return t;  // a, b, c on one great circle
  // cos α and sin α directly (no trigonometric call): the sampler needs only them.
  const double inv_length = 1.0 / std::sqrt(sin_scaled * sin_scaled + cos_scaled * cos_scaled);
  t.cos_alpha = cos_scaled * inv_length;
  t.sin_alpha = sin_scaled * inv_length;
  t.solid_angle_sr = spherical_triangle_solid_angle(t.a, t.b, t.c);
  return t;
}

Vec3d sample_spherical_triangle(const SphericalTriangle& t, Vec2d u) {
  // Arvo 1995, Fig. 2: choose Ĉ on the arc AC so that the sub-triangle (A, B, Ĉ) has area
  // u.x·Ω (the closed form for q = cos of the arc AĈ), then a point on the arc BĈ.
  const double sub_area = u.x * t.solid_angle_sr;
  // sin and cos of (sub_area − α) by the difference formulas: α is known by cos and sin.
  const double sin_area = std::sin(sub_area), cos_area = std::cos(sub_area);
  const double s = sin_area * t.cos_alpha - cos_area * t.sin_alpha;
  const double c = cos_area * t.cos_alpha + sin_area * t.sin_alpha;
  const double cos_ab = dot(t.a, t.b);  // cos of the edge opposite C
  const double uu = c - t.cos_alpha;
  const double v = s + t.sin_alpha * cos_ab;
  const double denominator = (v * s + uu * c) * t.sin_alpha;
  double q = denominator != 0.0 ? ((v * c - uu * s) * t.cos_alpha - v) / denominator : 1.0;
  q = std::clamp(q, -1.0, 1.0);
  const Vec3d c_hat = t.a * q + orthonormal_component(t.c, t.a) * std::sqrt(std::max(0.0, 1.0 - q * q));
  // 1 − cos(B, P) is uniform in u.y over [0, 1 − cos(B, Ĉ)].
  const double one_minus_z = u.y * one_minus_dot(c_hat, t.b);
  const double z = 1.0 - one_minus_z;
  const double sin_z = std::sqrt(std::max(0.0, one_minus_z * (2.0 - one_minus_z)));
  return t.b * z + orthonormal_component(c_hat, t.b) * sin_z;
}

Vec2d invert_spherical_triangle_sample(const SphericalTriangle& t, const Vec3d& w) {
  // Ĉ is where the great circle through B and w meets the arc AC.
  const Vec3d through_b = cross(t.b, w), through_ac = cross(t.a, t.c);
  Vec3d c_hat = cross(through_b, through_ac);
  const double len = length(c_hat);
  // w at B: every u.x gives it (u.y = 0); the pdf there does not depend on u.x.
  if (!(len > 1e-300)) return {0.5, 0.0};
  c_hat = c_hat / len;
  if (dot(c_hat, t.a + t.c) < 0.0) c_hat = -c_hat;  // the minor arc, between A and C
  const double u_x = t.solid_angle_sr > 0.0 ? spherical_triangle_solid_angle(t.a, t.b, c_hat) / t.solid_angle_sr : 0.0;
  const double arc = one_minus_dot(c_hat, t.b);
  const double u_y = arc > 0.0 ? one_minus_dot(w, t.b) / arc : 0.0;
  return {std::clamp(u_x, 0.0, 1.0), std::clamp(u_y, 0.0, 1.0)};
}

}  // namespace prism
