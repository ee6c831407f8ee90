// CIELAB per CIE 15:2004 eq. 8.3–8.7, with the linear segment below (6/29)³.
#include "prism/color/cielab.h"

#include <cmath>

namespace prism::color {
namespace {

double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

}  // namespace

Vec3d xyz_to_lab(const Vec3d& xyz, const Vec3d& white_xyz) {
  const double fx = lab_f(xyz.x / white_xyz.x);
  const double fy = lab_f(xyz.y / white_xyz.y);
  const double fz = lab_f(xyz.z / white_xyz.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

}  // namespace prism::color
