#include "prism/core/transform.h"

namespace prism {

Transform Transform::look_at(const Vec3f& eye, const Vec3f& target, const Vec3f& up) {
  const Vec3f forward = normalize(target - eye);
  const Vec3f left = normalize(cross(up, forward));
  const Vec3f true_up = cross(forward, left);
  Transform r;
  for (int i = 0; i < 3; ++i) {
    r.m[i][0] = left[i];
    r.m[i][1] = true_up[i];
    r.m[i][2] = forward[i];
  }
  r.translation = eye;
  return r;
}

Transform compose(const Transform& a, const Transform& b) {
  Transform r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  r.translation = a.apply_point(b.translation);
  return r;
}

}  // namespace prism
