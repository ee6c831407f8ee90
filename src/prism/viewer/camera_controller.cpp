// Camera motions for the viewer (camera_controller.h).
#include "prism/viewer/camera_controller.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prism::viewer {
namespace {

Vec3d d(const Vec3f& v) { return {v.x, v.y, v.z}; }
Vec3f f(const Vec3d& v) { return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}; }

// Rodrigues' rotation of v about the unit axis k by angle a.
Vec3d rotate(const Vec3d& v, const Vec3d& k, double a) {
  return v * std::cos(a) + cross(k, v) * std::sin(a) + k * (dot(k, v) * (1.0 - std::cos(a)));
}

// Rotates the direction `dir` by yaw about `up` and pitch about the right axis, keeping
// it at least 1° away from ±up.
Vec3d turn(const Vec3d& dir, const Vec3d& up_in, double yaw, double pitch) {
  const Vec3d up = normalize(up_in);
  const double len = length(dir);
  Vec3d v = rotate(dir / len, up, yaw);
  const double limit = std::numbers::pi / 2 - std::numbers::pi / 180;
  const double elevation = std::asin(std::clamp(dot(v, up), -1.0, 1.0));
  const double target = std::clamp(elevation + pitch, -limit, limit);
  const Vec3d right = normalize(cross(v, up));
  v = rotate(v, right, target - elevation);
  return v * len;
}

}  // namespace

double view_distance(const Camera& c) { return length(d(c.target) - d(c.eye)); }

Camera orbit(const Camera& c, double yaw, double pitch) {
  Camera out = c;
  // Orbiting moves the eye opposite to the view direction's turn.
  const Vec3d offset = d(c.eye) - d(c.target);
  out.eye = f(d(c.target) + turn(offset, d(c.up), yaw, -pitch));
  return out;
}

Camera look(const Camera& c, double yaw, double pitch) {
  Camera out = c;
  out.target = f(d(c.eye) + turn(d(c.target) - d(c.eye), d(c.up), yaw, pitch));
  return out;
}

Camera pan(const Camera& c, double right_amount, double up_amount) {
  const Vec3d forward = normalize(d(c.target) - d(c.eye));
  const Vec3d right = normalize(cross(forward, d(c.up)));
  const Vec3d up = cross(right, forward);
  const Vec3d move = right * right_amount + up * up_amount;
  Camera out = c;
  out.eye = f(d(c.eye) + move);
  out.target = f(d(c.target) + move);
  return out;
}

Camera fly(const Camera& c, double forward_amount, double right_amount, double up_amount) {
  const Vec3d forward = normalize(d(c.target) - d(c.eye));
  const Vec3d right = normalize(cross(forward, d(c.up)));
  const Vec3d move = forward * forward_amount + right * right_amount + normalize(d(c.up)) * up_amount;
  Camera out = c;
  out.eye = f(d(c.eye) + move);
  out.target = f(d(c.target) + move);
  return out;
}

Camera dolly(const Camera& c, double factor) {
  const Vec3d offset = d(c.eye) - d(c.target);
  Camera out = c;
  out.eye = f(d(c.target) + offset * std::max(factor, 1e-4));
  return out;
}

double pixel_footprint(const Camera& c, int image_height_px) {
  const double half = std::tan(c.fov_degrees * std::numbers::pi / 360.0);
  return 2.0 * half * view_distance(c) / std::max(image_height_px, 1);
}

}  // namespace prism::viewer
