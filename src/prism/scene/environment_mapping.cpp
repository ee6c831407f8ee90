#include "prism/scene/environment_mapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "prism/sampling/equal_area_sphere.h"

namespace prism {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Equirectangular: v = θ/π from +y (top row) down, u = (φ + π)/2π with φ = atan2(z, x).
Vec2f direction_to_equirect(const Vec3f& d) {
  const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
  const float phi = std::atan2(d.z, d.x);
  return {(phi + kPi) / (2.0f * kPi), theta / kPi};
}

Vec3f equirect_to_direction(Vec2f uv) {
  const float phi = uv.x * 2.0f * kPi - kPi, theta = uv.y * kPi;
  const float sin_theta = std::sin(theta);
  return {sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi)};
}

}  // namespace

Vec2f environment_direction_to_uv(EnvironmentMapping mapping, const Vec3f& direction) {
  if (mapping == EnvironmentMapping::equal_area_octahedral) return equal_area_sphere_to_square(direction);
  return direction_to_equirect(direction);
}

Vec3f environment_uv_to_direction(EnvironmentMapping mapping, Vec2f uv) {
  if (mapping == EnvironmentMapping::equal_area_octahedral) return equal_area_square_to_sphere(uv);
  return equirect_to_direction(uv);
}

float environment_solid_angle_per_uv_area(EnvironmentMapping mapping, Vec2f uv) {
  if (mapping == EnvironmentMapping::equal_area_octahedral) return 4.0f * kPi;
  // dω = sin θ dθ dφ with dθ = π dv and dφ = 2π du.
  return 2.0f * kPi * kPi * std::sin(uv.y * kPi);
}

}  // namespace prism
