#include "prism/sampling/equal_area_sphere.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism {

// With a = |2u − 1| and b = |2v − 1| on one quadrant of the unfolded octahedron, the upper
// hemisphere is the triangle a + b ≤ 1. Clarberg's map takes r = a + b (the L1 distance
// from the centre) to the cap z ≥ 1 − r², whose area 2πr² is π times the triangle-quadrants'
// area 2r², and spreads φ ∈ [0, π/2] linearly along the line a + b = r: φ = (π/2) · b / r.
// Both steps preserve area, so the whole map does (Clarberg 2008, §2–3). The lower
// hemisphere is the same map after folding the corner triangle a + b > 1 onto the diamond:
// (a, b) → (1 − b, 1 − a).
Vec3f equal_area_square_to_sphere(Vec2f p) {
  const float su = 2.0f * p.x - 1.0f, sv = 2.0f * p.y - 1.0f;
  float a = std::abs(su), b = std::abs(sv);
  const bool lower = a + b > 1.0f;
  if (lower) {
    const float folded_a = 1.0f - b;
    b = 1.0f - a;
    a = folded_a;
  }
  const float r = a + b;
  const float phi = r > 0.0f ? 0.5f * std::numbers::pi_v<float> * (b / r) : 0.0f;
  const float z = 1.0f - r * r;
  const float sin_theta = r * std::sqrt(std::max(0.0f, 2.0f - r * r));  // sqrt(1 − z²)
  return {std::copysign(std::cos(phi) * sin_theta, su), std::copysign(std::sin(phi) * sin_theta, sv),
          lower ? -z : z};
}

Vec2f equal_area_sphere_to_square(const Vec3f& direction) {
  const Vec3f d = normalize(direction);
  const float r = std::sqrt(std::max(0.0f, 1.0f - std::abs(d.z)));
  // φ in the quadrant, from the larger of |x|, |y| so the quotient stays in [0, 1].
  const float x = std::abs(d.x), y = std::abs(d.y);
  float phi_fraction = 0.0f;  // φ / (π/2)
  if (x > 0.0f || y > 0.0f)
    phi_fraction = x >= y ? std::atan(y / x) * (2.0f / std::numbers::pi_v<float>)
                          : 1.0f - std::atan(x / y) * (2.0f / std::numbers::pi_v<float>);
  float b = r * phi_fraction, a = r - b;
  if (d.z < 0.0f) {
    const float unfolded_a = 1.0f - b;
    b = 1.0f - a;
    a = unfolded_a;
  }
  return {0.5f * (std::copysign(a, d.x) + 1.0f), 0.5f * (std::copysign(b, d.y) + 1.0f)};
}

}  // namespace prism
