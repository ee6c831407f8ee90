// The equal-area octahedral map (Clarberg 2008; pbrt-v4 §3.8.3): round trips, pbrt-v4's
// orientation of the square, and equal area in both directions by chi-square.
#include "prism/sampling/equal_area_sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"
#include "support/chi_square.h"

namespace prism {
namespace {

constexpr int kEqualAreaChiSquareTests = 2;  // test::kAlphaTotal is Šidák-split over these

TEST(EqualAreaSphere, DirectionToSquareAndBackIsTheIdentity) {
  // Float rounding only: sqrt, atan and sin/cos each err by an ulp or two, so 4e-6 is
  // ~30 ε on a unit vector; a wrong fold or sign errs by O(1).
  constexpr float kTolerance = 4e-6f;
  Pcg32 rng(7, 3);
  std::vector<Vec3f> directions = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {1, 1, 0},  {-1, 1, 0}, {1, 0, -1}, {0, -1, -1},
                                   {1, 1, 1},  {-1, -1, -1}, {0.3f, -0.2f, -0.9f}};
  for (int i = 0; i < 200'000; ++i) directions.push_back(sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float())));
  for (Vec3f d : directions) {
    d = normalize(d);
    const Vec2f uv = equal_area_sphere_to_square(d);
    ASSERT_GE(uv.x, 0.0f);
    ASSERT_LE(uv.x, 1.0f);
    ASSERT_GE(uv.y, 0.0f);
    ASSERT_LE(uv.y, 1.0f);
    const Vec3f back = equal_area_square_to_sphere(uv);
    ASSERT_NEAR(length(back), 1.0f, kTolerance);
    ASSERT_LT(length(back - d), kTolerance) << d.x << " " << d.y << " " << d.z;
  }
}

TEST(EqualAreaSphere, SquareToDirectionAndBackIsTheIdentity) {
  // Inside the square (the edges are folded onto themselves, so a point there may come
  // back as its mirror image). Near the poles z = 1 − r² cancels: r comes back with an
  // error of about ε / (2r), 3e-5 at r = 1e-3 (the smallest r these samples reach is about
  // that), hence 1e-4; a wrong branch errs by O(0.1).
  Pcg32 rng(11, 5);
  for (int i = 0; i < 200'000; ++i) {
    const Vec2f uv(0.001f + 0.998f * rng.next_float(), 0.001f + 0.998f * rng.next_float());
    const Vec2f back = equal_area_sphere_to_square(equal_area_square_to_sphere(uv));
    ASSERT_NEAR(back.x, uv.x, 1e-4f) << uv.x << " " << uv.y;
    ASSERT_NEAR(back.y, uv.y, 1e-4f) << uv.x << " " << uv.y;
  }
}

TEST(EqualAreaSphere, FollowsPbrtV4Orientation) {
  // pbrt-v4 book §3.8.3, Figure 3.18 and EqualAreaSquareToSphere(): the square's centre
  // is +z, its corners −z, x takes the sign of 2u − 1 and y the sign of 2v − 1, the
  // midpoints of the edges are ±x, ±y on the equator.
  const auto near = [](Vec2f a, Vec2f b) { return std::abs(a.x - b.x) < 1e-6f && std::abs(a.y - b.y) < 1e-6f; };
  EXPECT_TRUE(near(equal_area_sphere_to_square({0, 0, 1}), {0.5f, 0.5f}));
  EXPECT_TRUE(near(equal_area_sphere_to_square({1, 0, 0}), {1.0f, 0.5f}));
  EXPECT_TRUE(near(equal_area_sphere_to_square({-1, 0, 0}), {0.0f, 0.5f}));
  EXPECT_TRUE(near(equal_area_sphere_to_square({0, 1, 0}), {0.5f, 1.0f}));
  EXPECT_TRUE(near(equal_area_sphere_to_square({0, -1, 0}), {0.5f, 0.0f}));
  EXPECT_TRUE(near(equal_area_sphere_to_square(normalize(Vec3f(1, 1, 0))), {0.75f, 0.75f}));
  const Vec3f corner = equal_area_square_to_sphere({0.0f, 1.0f});
  EXPECT_NEAR(corner.z, -1.0f, 1e-6f);
  // The octant x, y, z > 0 is the triangle u, v > 1/2, u + v < 3/2.
  const Vec3f d = equal_area_square_to_sphere({0.6f, 0.7f});
  EXPECT_GT(d.x, 0.0f);
  EXPECT_GT(d.y, 0.0f);
  EXPECT_GT(d.z, 0.0f);
  const Vec3f e = equal_area_square_to_sphere({0.1f, 0.2f});  // u + v < 1/2: −x, −y, lower
  EXPECT_LT(e.x, 0.0f);
  EXPECT_LT(e.y, 0.0f);
  EXPECT_LT(e.z, 0.0f);
}

TEST(EqualAreaSphere, UniformSquareGivesUniformSphere) {
  const auto h = test::spherical_histogram(
      [](Vec2f u, Vec3f& d) {
        d = equal_area_square_to_sphere(u);
        return true;
      },
      [](const Vec3f&) { return 0.25 * std::numbers::inv_pi; }, 20, 40, 1'000'000, 19);
  const auto r = test::chi_square_test(h.observed, h.expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kEqualAreaChiSquareTests)) << r.message;
}

TEST(EqualAreaSphere, UniformSphereGivesUniformSquare) {
  // Each cell of a 24 × 24 grid on the square holds 1/576 of the sphere's area.
  constexpr int kGrid = 24;
  constexpr long kSamples = 1'000'000;
  std::vector<double> observed(kGrid * kGrid, 0.0), expected(kGrid * kGrid, double(kSamples) / (kGrid * kGrid));
  Pcg32 rng(23, 29);
  for (long i = 0; i < kSamples; ++i) {
    const Vec2f uv = equal_area_sphere_to_square(sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float())));
    const int x = std::clamp(static_cast<int>(uv.x * kGrid), 0, kGrid - 1);
    const int y = std::clamp(static_cast<int>(uv.y * kGrid), 0, kGrid - 1);
    observed[static_cast<std::size_t>(y * kGrid + x)] += 1.0;
  }
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kEqualAreaChiSquareTests)) << r.message;
}

}  // namespace
}  // namespace prism
