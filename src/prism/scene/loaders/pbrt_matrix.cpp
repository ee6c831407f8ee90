#include "prism/scene/loaders/pbrt_matrix.h"

#include <cmath>
#include <numbers>

namespace prism::loaders {

PbrtMatrix operator*(const PbrtMatrix& a, const PbrtMatrix& b) {
  PbrtMatrix r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

PbrtMatrix PbrtMatrix::translate(double x, double y, double z) {
  PbrtMatrix r;
  r.m[0][3] = x;
  r.m[1][3] = y;
  r.m[2][3] = z;
  return r;
}

PbrtMatrix PbrtMatrix::scale(double x, double y, double z) {
  PbrtMatrix r;
  r.m[0][0] = x;
  r.m[1][1] = y;
  r.m[2][2] = z;
  return r;
}

// Rodrigues' rotation about a unit axis.
PbrtMatrix PbrtMatrix::rotate(double angle_degrees, double x, double y, double z) {
  const double len = std::sqrt(x * x + y * y + z * z);
  PbrtMatrix r;
  if (!(len > 0.0)) return r;
  x /= len, y /= len, z /= len;
  const double t = angle_degrees * std::numbers::pi / 180.0, c = std::cos(t), s = std::sin(t), d = 1.0 - c;
  r.m[0] = {x * x * d + c, x * y * d - z * s, x * z * d + y * s, 0};
  r.m[1] = {x * y * d + z * s, y * y * d + c, y * z * d - x * s, 0};
  r.m[2] = {x * z * d - y * s, y * z * d + x * s, z * z * d + c, 0};
  return r;
}

std::optional<PbrtMatrix> PbrtMatrix::look_at(const double eye[3], const double target[3], const double up[3]) {
  const auto cross = [](const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
  };
  const auto normalize = [](double v[3]) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(l > 0.0) || !std::isfinite(l)) return false;
    for (int i = 0; i < 3; ++i) v[i] /= l;
    return true;
  };
  double dir[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
  double u[3] = {up[0], up[1], up[2]};
  if (!normalize(dir) || !normalize(u)) return std::nullopt;
  double right[3], new_up[3];
  cross(u, dir, right);
  if (!normalize(right)) return std::nullopt;
  cross(dir, right, new_up);
  // World-from-camera has columns (right, up, dir, eye); pbrt's LookAt is its inverse.
  PbrtMatrix world_from_camera;
  for (int i = 0; i < 3; ++i) {
    world_from_camera.m[i][0] = right[i];
    world_from_camera.m[i][1] = new_up[i];
    world_from_camera.m[i][2] = dir[i];
    world_from_camera.m[i][3] = eye[i];
  }
  return world_from_camera.inverse();
}

double PbrtMatrix::determinant3() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool PbrtMatrix::is_affine() const { return m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1; }

// Gauss–Jordan elimination with partial pivoting.
std::optional<PbrtMatrix> PbrtMatrix::inverse() const {
  double a[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      a[i][j] = m[i][j];
      a[i][j + 4] = i == j ? 1.0 : 0.0;
    }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-300)) return std::nullopt;
    for (int j = 0; j < 8; ++j) std::swap(a[col][j], a[pivot][j]);
    const double inv = 1.0 / a[col][col];
    for (int j = 0; j < 8; ++j) a[col][j] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
    }
  }
  PbrtMatrix r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a[i][j + 4];
  for (const auto& row : r.m)
    for (double v : row)
      if (!std::isfinite(v)) return std::nullopt;
  return r;
}

Transform PbrtMatrix::to_transform() const {
  Transform t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.m[i][j] = static_cast<float>(m[i][j]);
  t.translation = Vec3f(static_cast<float>(m[0][3]), static_cast<float>(m[1][3]), static_cast<float>(m[2][3]));
  return t;
}

}  // namespace prism::loaders
