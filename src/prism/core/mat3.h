#pragma once
// Row-major 3x3 matrix in double precision: colour-space conversions and linear maps.
#include <array>

#include "prism/core/vec.h"

namespace prism {

struct Mat3 {
  std::array<std::array<double, 3>, 3> m{};

  static constexpr Mat3 identity() {
    Mat3 r;
    r.m[0][0] = r.m[1][1] = r.m[2][2] = 1.0;
    return r;
  }
  static constexpr Mat3 diagonal(const Vec3d& d) {
    Mat3 r;
    r.m[0][0] = d.x;
    r.m[1][1] = d.y;
    r.m[2][2] = d.z;
    return r;
  }
  static constexpr Mat3 from_columns(const Vec3d& c0, const Vec3d& c1, const Vec3d& c2) {
    Mat3 r;
    for (int i = 0; i < 3; ++i) {
      r.m[i][0] = c0[i];
      r.m[i][1] = c1[i];
      r.m[i][2] = c2[i];
    }
    return r;
  }

  constexpr double operator()(int row, int col) const { return m[row][col]; }
  constexpr double& operator()(int row, int col) { return m[row][col]; }
  constexpr Vec3d row(int i) const { return {m[i][0], m[i][1], m[i][2]}; }
  constexpr Vec3d column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
};

constexpr Vec3d operator*(const Mat3& a, const Vec3d& v) {
  return {dot(a.row(0), v), dot(a.row(1), v), dot(a.row(2), v)};
}

constexpr Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = dot(a.row(i), b.column(j));
  return r;
}

constexpr Mat3 transpose(const Mat3& a) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

constexpr double determinant(const Mat3& a) { return dot(a.row(0), cross(a.row(1), a.row(2))); }

// Inverse by the adjugate; the caller guarantees a non-singular matrix (check determinant()).
constexpr Mat3 inverse(const Mat3& a) {
  const Vec3d c0 = cross(a.row(1), a.row(2));
  const Vec3d c1 = cross(a.row(2), a.row(0));
  const Vec3d c2 = cross(a.row(0), a.row(1));
  const double inv_det = 1.0 / dot(a.row(0), c0);
  return Mat3::from_columns(c0 * inv_det, c1 * inv_det, c2 * inv_det);
}

}  // namespace prism
