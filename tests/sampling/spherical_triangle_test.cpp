// Arvo's spherical-triangle map and the bilinear warp: exact solid angles, the map's
// inverse, and chi-square tests of both densities.
#include "prism/sampling/spherical_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "prism/core/pcg32.h"
#include "prism/sampling/bilinear_warp.h"
#include "support/chi_square.h"

namespace prism {
namespace {

constexpr int kSphericalTriangleChiSquareTests = 4;  // test::kAlphaTotal is Šidák-split over these

TEST(SphericalTriangle, SolidAngleOfAnOctantIsHalfPi) {
  // The triangle with vertices on the three axes covers one eighth of the sphere: 4π/8.
  const SphericalTriangle t =
      make_spherical_triangle(Vec3d(0.0), Vec3d(2, 0, 0), Vec3d(0, 3, 0), Vec3d(0, 0, 0.5));
  EXPECT_NEAR(t.solid_angle_sr, std::numbers::pi / 2.0, 1e-12);
  EXPECT_NEAR(t.cos_alpha, 0.0, 1e-12);  // right angles at every vertex
  EXPECT_NEAR(t.sin_alpha, 1.0, 1e-12);
}

TEST(SphericalTriangle, SmallTriangleMatchesProjectedArea) {
  // A 1e-3 × 1e-3 right triangle at distance 1, facing the centre: Ω → A / r² = 5e-7 as
  // the triangle shrinks; the relative difference is O(size²) = 1e-6.
  const SphericalTriangle t =
      make_spherical_triangle(Vec3d(0.0), Vec3d(0, 0, 1), Vec3d(1e-3, 0, 1), Vec3d(0, 1e-3, 1));
  EXPECT_NEAR(t.solid_angle_sr, 5e-7, 5e-7 * 2e-6);
}

TEST(SphericalTriangle, CornersMapToVertices) {
  const SphericalTriangle t = make_spherical_triangle(Vec3d(0.1, 0.2, -1.0), Vec3d(-1, 0, 1), Vec3d(1, 0.2, 1.5),
                                                      Vec3d(0.3, 1, 0.8));
  // Where Ĉ → A, q → 1 and √(1 − q²) turns q's rounding (1e-16) into √(2e-16) ≈ 1.5e-8.
  const auto near = [](const Vec3d& x, const Vec3d& y) { return length(x - y) < 1e-7; };
  EXPECT_TRUE(near(sample_spherical_triangle(t, {0.0, 0.0}), t.b));
  EXPECT_TRUE(near(sample_spherical_triangle(t, {1.0, 0.0}), t.b));
  EXPECT_TRUE(near(sample_spherical_triangle(t, {0.0, 1.0}), t.a));
  EXPECT_TRUE(near(sample_spherical_triangle(t, {1.0, 1.0}), t.c));
}

TEST(SphericalTriangle, InverseRecoversTheSquarePoint) {
  Pcg32 rng(11, 12);
  for (int k = 0; k < 200; ++k) {
    const auto point = [&] { return Vec3d(rng.next_double() * 2 - 1, rng.next_double() * 2 - 1, 1.0 + rng.next_double()); };
    const SphericalTriangle t = make_spherical_triangle(Vec3d(0.0), point(), point(), point());
    if (t.solid_angle_sr < 1e-3) continue;
    for (int i = 0; i < 20; ++i) {
      const Vec2d u(rng.next_double(), rng.next_double());
      const Vec3d w = sample_spherical_triangle(t, u);
      ASSERT_NEAR(length(w), 1.0, 1e-12);
      const Vec2d back = invert_spherical_triangle_sample(t, w);
      // u.x is not defined where w = B (u.y = 0); elsewhere both are recovered to ~1e-9
      // (double rounding through trigonometric functions, amplified near that corner).
      ASSERT_NEAR(back.y, u.y, 1e-7) << k << " " << u.x << " " << u.y;
      if (u.y > 1e-3) {
        ASSERT_NEAR(back.x, u.x, 1e-6) << k << " " << u.x << " " << u.y;
      }
    }
  }
}

// Chi-square of directions against the uniform density 1/Ω, binned by geometry: the strip
// index is the solid angle of the sub-triangle (A, B, Ĉ) cut off by the great circle
// through B and the direction (Van Oosterom–Strackee, not Arvo's formula), as a fraction
// of Ω; the cell within the strip is (1 − cos(w, B)) / (1 − cos(Ĉ, B)). Under a uniform
// density both are uniform and independent (the sub-triangle has exactly that share of
// the solid angle; in a thin wedge around B the area element is d(cos θ) dφ), so every
// cell expects N / bins².
TEST(SphericalTriangle, DirectionsAreUniformInSolidAngle) {
  const SphericalTriangle t = make_spherical_triangle(Vec3d(0.0), Vec3d(-1, -0.5, 1), Vec3d(1.5, -0.2, 1.2),
                                                      Vec3d(0.1, 1.3, 0.7));
  constexpr int kBins = 12;
  constexpr long kSamples = 300'000;
  std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, double(kSamples) / (kBins * kBins));
  Pcg32 rng(21, 22);
  for (long i = 0; i < kSamples; ++i) {
    const Vec3d w = sample_spherical_triangle(t, Vec2d(rng.next_double(), rng.next_double()));
    const Vec3d n1 = cross(t.b, w), n2 = cross(t.a, t.c);
    Vec3d c_hat = normalize(cross(n1, n2));
    if (dot(c_hat, t.a + t.c) < 0.0) c_hat = -c_hat;
    const double fx = spherical_triangle_solid_angle(t.a, t.b, c_hat) / t.solid_angle_sr;
    const double fy = (1.0 - dot(w, t.b)) / (1.0 - dot(c_hat, t.b));
    const int ix = std::clamp(static_cast<int>(fx * kBins), 0, kBins - 1);
    const int iy = std::clamp(static_cast<int>(fy * kBins), 0, kBins - 1);
    observed[static_cast<std::size_t>(iy * kBins + ix)] += 1.0;
  }
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kSphericalTriangleChiSquareTests)) << r.message;
}

// The same directions binned on the plane z = 1 (a gnomonic chart), against 1/Ω integrated
// over each chart cell with the Jacobian dω = dA cos/r² = dA / (1 + x² + y²)^{3/2}: a
// check independent of the triangle's own parameterisation.
TEST(SphericalTriangle, DirectionsMatchUniformDensityOnAPlane) {
  const Vec3d p0(-0.6, -0.5, 1.0), p1(0.7, -0.4, 1.0), p2(0.1, 0.8, 1.0);
  const SphericalTriangle t = make_spherical_triangle(Vec3d(0.0), p0, p1, p2);
  constexpr int kBins = 16;
  constexpr long kSamples = 300'000;
  const double x_min = -0.6, x_max = 0.7, y_min = -0.5, y_max = 0.8;
  const double dx = (x_max - x_min) / kBins, dy = (y_max - y_min) / kBins;
  const auto inside = [&](double x, double y) {
    const auto edge = [](const Vec3d& a, const Vec3d& b, double px, double py) {
      return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
    };
    const double e0 = edge(p0, p1, x, y), e1 = edge(p1, p2, x, y), e2 = edge(p2, p0, x, y);
    return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
  };
  std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, 0.0);
  Pcg32 rng(31, 32);
  for (long i = 0; i < kSamples; ++i) {
    const Vec3d w = sample_spherical_triangle(t, Vec2d(rng.next_double(), rng.next_double()));
    const double x = w.x / w.z, y = w.y / w.z;
    const int ix = std::clamp(static_cast<int>((x - x_min) / dx), 0, kBins - 1);
    const int iy = std::clamp(static_cast<int>((y - y_min) / dy), 0, kBins - 1);
    observed[static_cast<std::size_t>(iy * kBins + ix)] += 1.0;
  }
  // Midpoint rule with 32² points per cell: the triangle's edges cut cells, so the
  // integral converges as O(1/32) there; that error (< 1 % of an edge cell's mass) is far
  // below the chi-square's resolution at these counts (√(N/bins) ≈ 4 %).
  constexpr int kSub = 32;
  for (int iy = 0; iy < kBins; ++iy)
    for (int ix = 0; ix < kBins; ++ix) {
      double sum = 0.0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          const double x = x_min + dx * (ix + (a + 0.5) / kSub), y = y_min + dy * (iy + (b + 0.5) / kSub);
          if (inside(x, y)) sum += std::pow(1.0 + x * x + y * y, -1.5);
        }
      expected[static_cast<std::size_t>(iy * kBins + ix)] =
          sum * (dx / kSub) * (dy / kSub) / t.solid_angle_sr * kSamples;
    }
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kSphericalTriangleChiSquareTests)) << r.message;
}

TEST(BilinearWarp, DensityIntegratesToOne) {
  const BilinearWeights w{0.2, 1.5, 0.01, 0.7};
  constexpr int kN = 200;
  double sum = 0.0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) sum += bilinear_pdf({(i + 0.5) / kN, (j + 0.5) / kN}, w);
  // The midpoint rule is exact for bilinear functions: only rounding remains.
  EXPECT_NEAR(sum / (kN * kN), 1.0, 1e-12);
}

TEST(BilinearWarp, SamplesFollowTheBilinearDensity) {
  for (const BilinearWeights w : {BilinearWeights{0.2, 1.5, 0.01, 0.7}, BilinearWeights{1.0, 0.05, 0.9, 0.3}}) {
    constexpr int kBins = 16;
    constexpr long kSamples = 200'000;
    std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, 0.0);
    Pcg32 rng(41, 42);
    for (long i = 0; i < kSamples; ++i) {
      const Vec2d p = sample_bilinear({rng.next_double(), rng.next_double()}, w);
      ASSERT_GE(p.x, 0.0);
      ASSERT_LT(p.x, 1.0);
      ASSERT_GE(p.y, 0.0);
      ASSERT_LT(p.y, 1.0);
      observed[static_cast<std::size_t>(static_cast<int>(p.y * kBins) * kBins + static_cast<int>(p.x * kBins))] += 1.0;
    }
    for (int iy = 0; iy < kBins; ++iy)
      for (int ix = 0; ix < kBins; ++ix)  // midpoint rule: exact for a bilinear density
        expected[static_cast<std::size_t>(iy * kBins + ix)] =
            bilinear_pdf({(ix + 0.5) / kBins, (iy + 0.5) / kBins}, w) * kSamples / (kBins * kBins);
    const auto r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kSphericalTriangleChiSquareTests)) << r.message;
  }
}

}  // namespace
}  // namespace prism
