#include <gtest/gtest.h>

#include "prism/core/bounds.h"
#include "prism/core/frame.h"
#include "prism/core/mat3.h"
#include "prism/core/pcg32.h"
#include "prism/core/transform.h"
#include "prism/core/vec.h"

namespace prism {
namespace {

TEST(Vec3, ArithmeticDotCross) {
  const Vec3f a(1, 2, 3), b(4, 5, 6);
  EXPECT_EQ(a + b, Vec3f(5, 7, 9));
  EXPECT_EQ(b - a, Vec3f(3, 3, 3));
  EXPECT_EQ(a * 2.0f, Vec3f(2, 4, 6));
  EXPECT_FLOAT_EQ(dot(a, b), 32.0f);
  EXPECT_EQ(cross(Vec3f(1, 0, 0), Vec3f(0, 1, 0)), Vec3f(0, 0, 1));
  EXPECT_FLOAT_EQ(length(Vec3f(3, 4, 0)), 5.0f);
  EXPECT_FLOAT_EQ(max_component(a), 3.0f);
  EXPECT_FALSE(is_finite(Vec3f(1, std::numeric_limits<float>::quiet_NaN(), 0)));
}

// The frame must be orthonormal and right-handed for any normal, including the poles
// where naive constructions divide by zero (Duff et al. 2017 test both signs of z).
TEST(Frame, OrthonormalRightHandedForAllNormals) {
  Pcg32 rng(3, 4);
  std::vector<Vec3f> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0.0001f, -1}};
  for (int i = 0; i < 10000; ++i) {
    Vec3f v(rng.next_float() * 2 - 1, rng.next_float() * 2 - 1, rng.next_float() * 2 - 1);
    if (length(v) > 1e-3f) normals.push_back(normalize(v));
  }
  for (const Vec3f& n : normals) {
    const Frame f = Frame::from_normal(normalize(n));
    // Single-precision construction: errors of a few ulps of 1 (≈1e-7) per component.
    EXPECT_NEAR(length(f.s), 1.0f, 1e-5f);
    EXPECT_NEAR(length(f.t), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.t, f.n), 0.0f, 1e-5f);
    const Vec3f c = cross(f.s, f.t);
    EXPECT_NEAR(dot(c, f.n), 1.0f, 1e-5f);
    const Vec3f w(0.3f, -0.2f, 0.5f);
    const Vec3f back = f.to_world(f.to_local(w));
    EXPECT_NEAR(length(back - w), 0.0f, 1e-5f);
  }
}

TEST(Transform, LookAtMapsAxes) {
  const Transform t = Transform::look_at(Vec3f(278, 273, -800), Vec3f(278, 273, -799), Vec3f(0, 1, 0));
  const Vec3f forward = t.apply_vector(Vec3f(0, 0, 1));
  const Vec3f up = t.apply_vector(Vec3f(0, 1, 0));
  const Vec3f left = t.apply_vector(Vec3f(1, 0, 0));
  EXPECT_NEAR(length(forward - Vec3f(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_NEAR(length(up - Vec3f(0, 1, 0)), 0.0f, 1e-6f);
  // Looking down +z with +y up, the viewer's left is +x in a right-handed world.
  EXPECT_NEAR(length(left - Vec3f(1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(t.apply_point(Vec3f(0, 0, 0)), Vec3f(278, 273, -800));
}

TEST(Transform, ComposeAppliesRightThenLeft) {
  const Transform s = Transform::scale(Vec3f(2, 3, 4));
  const Transform tr = Transform::translate(Vec3f(1, 1, 1));
  EXPECT_EQ(compose(tr, s).apply_point(Vec3f(1, 1, 1)), Vec3f(3, 4, 5));
  EXPECT_EQ(compose(s, tr).apply_point(Vec3f(1, 1, 1)), Vec3f(4, 6, 8));
}

TEST(Bounds, ExtendAndContain) {
  Bounds3f b;
  EXPECT_TRUE(b.empty());
  b.extend(Vec3f(1, 2, 3));
  b.extend(Vec3f(-1, 0, 5));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.lower, Vec3f(-1, 0, 3));
  EXPECT_EQ(b.upper, Vec3f(1, 2, 5));
  EXPECT_TRUE(b.contains(Vec3f(0, 1, 4)));
  EXPECT_FALSE(b.contains(Vec3f(0, 1, 6)));
  EXPECT_EQ(b.center(), Vec3f(0, 1, 4));
}

TEST(Mat3, InverseAndProduct) {
  Mat3 a;
  a.m = {{{2, 1, 0}, {0, 3, 1}, {1, 0, 4}}};
  const Mat3 p = a * inverse(a);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p(i, j), i == j ? 1.0 : 0.0, 1e-14);
  EXPECT_DOUBLE_EQ(determinant(a), 25.0);
  const Vec3d v = a * Vec3d(1, 1, 1);
  EXPECT_EQ(v, Vec3d(3, 4, 5));
}

}  // namespace
}  // namespace prism
