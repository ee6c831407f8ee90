#pragma once
// Affine transforms as a 3x3 linear part plus translation, in single precision.
#include "prism/core/vec.h"

namespace prism {

struct Transform {
  // Row-major linear part.
  float m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3f translation{};

  bool operator==(const Transform&) const = default;

  static Transform translate(const Vec3f& t) {
    Transform r;
    r.translation = t;
    return r;
  }
  static Transform scale(const Vec3f& s) {
    Transform r;
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
  }
  // Camera-to-world transform of a right-handed camera at `eye` looking at `target`:
  // local +z is the viewing direction, +y is up and +x points to the image's left, so
  // that (right, up, forward) map to (-x, +y, +z) as in pbrt's LookAt.
  static Transform look_at(const Vec3f& eye, const Vec3f& target, const Vec3f& up);

  Vec3f apply_vector(const Vec3f& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  Vec3f apply_point(const Vec3f& p) const { return apply_vector(p) + translation; }
};

// a ∘ b: apply b first, then a.
Transform compose(const Transform& a, const Transform& b);

}  // namespace prism
