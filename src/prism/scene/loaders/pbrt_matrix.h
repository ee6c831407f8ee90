#pragma once
// 4×4 matrices in double precision for pbrt-v4's transform directives (the current
// transformation matrix is composed in double and converted to prism::Transform at use).
#include <array>
#include <optional>

#include "prism/core/transform.h"

namespace prism::loaders {

struct PbrtMatrix {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

  static PbrtMatrix translate(double x, double y, double z);
  static PbrtMatrix scale(double x, double y, double z);
  static PbrtMatrix rotate(double angle_degrees, double x, double y, double z);  // axis need not be unit
  // pbrt's LookAt: the camera-from-world matrix of a camera at `eye` looking at `target`.
  static std::optional<PbrtMatrix> look_at(const double eye[3], const double target[3], const double up[3]);

  std::optional<PbrtMatrix> inverse() const;
  double determinant3() const;  // of the upper-left 3×3 block
  bool is_affine() const;       // bottom row (0 0 0 1)
  Transform to_transform() const;  // drops a projective bottom row
};

PbrtMatrix operator*(const PbrtMatrix& a, const PbrtMatrix& b);

}  // namespace prism::loaders
