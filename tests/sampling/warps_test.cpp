#include "prism/sampling/warps.h"

#include <gtest/gtest.h>

#include <numbers>

#include "prism/core/pcg32.h"
#include "support/chi_square.h"

namespace prism {
namespace {

// Overall false-alarm rate of this file's chi-square tests, split by Šidák's correction.
constexpr double kAlphaTotal = 0.01;
constexpr int kChiSquareTests = 2;

TEST(Warps, ConcentricDiskStaysInDisk) {
  Pcg32 rng(1, 1);
  for (int i = 0; i < 100000; ++i) {
    const Vec2f d = sample_concentric_disk(Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_LE(d.x * d.x + d.y * d.y, 1.0f + 1e-6f);
  }
}

TEST(Warps, CosineHemisphereMatchesItsPdf) {
  const auto h = test::spherical_histogram(
      [](Vec2f u, Vec3f& d) {
        d = sample_cosine_hemisphere(u);
        return true;
      },
      [](const Vec3f& d) { return static_cast<double>(cosine_hemisphere_pdf(d.z)); }, 20, 40, 1'000'000, 42);
  const auto r = test::chi_square_test(h.observed, h.expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(kAlphaTotal, kChiSquareTests)) << r.message;
}

// Uniform triangle sampling: histogram the barycentric (b1, b2) over a grid on the unit
// square; the expected mass of a cell is 2 × (its area inside the triangle b1 + b2 ≤ 1),
// integrated by subdivision.
TEST(Warps, UniformTriangleIsUniform) {
  constexpr int kGrid = 30;
  constexpr long kSamples = 1'000'000;
  std::vector<double> observed(kGrid * kGrid, 0.0), expected(kGrid * kGrid, 0.0);
  Pcg32 rng(9, 2);
  for (long i = 0; i < kSamples; ++i) {
    const Vec2f b = sample_uniform_triangle(Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_GE(b.x, 0.0f);
    ASSERT_GE(b.y, 0.0f);
    ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
    const int ix = std::min(kGrid - 1, static_cast<int>(b.x * kGrid));
    const int iy = std::min(kGrid - 1, static_cast<int>(b.y * kGrid));
    observed[static_cast<std::size_t>(iy * kGrid + ix)] += 1.0;
  }
  constexpr int kSub = 64;
  for (int iy = 0; iy < kGrid; ++iy)
    for (int ix = 0; ix < kGrid; ++ix) {
      int inside = 0;
      for (int a = 0; a < kSub; ++a)
        for (int c = 0; c < kSub; ++c) {
          const double x = (ix + (a + 0.5) / kSub) / kGrid, y = (iy + (c + 0.5) / kSub) / kGrid;
          inside += x + y <= 1.0;
        }
      expected[static_cast<std::size_t>(iy * kGrid + ix)] =
          2.0 * kSamples * inside / double(kSub * kSub) / double(kGrid * kGrid);
    }
  // Cells cut by the diagonal carry a midpoint-rule error of O(1/kSub²) relative mass,
  // far below the statistical noise of ~1000 samples per cell.
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(kAlphaTotal, kChiSquareTests)) << r.message;
}

TEST(Warps, PowerHeuristic) {
  EXPECT_FLOAT_EQ(power_heuristic(1.0f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(power_heuristic(3.0f, 1.0f), 0.9f);
  EXPECT_FLOAT_EQ(power_heuristic(0.0f, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(power_heuristic(2.0f, 5.0f) + power_heuristic(5.0f, 2.0f), 1.0f);
}

}  // namespace
}  // namespace prism
