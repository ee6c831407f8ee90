#include "prism/sampling/warps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "prism/core/pcg32.h"
#include "support/chi_square.h"

namespace prism {
namespace {

// Overall false-alarm rate of this file's chi-square tests, split by Šidák's correction.
constexpr int kWarpChiSquareTests = 2;

TEST(Warps, ConcentricDiskStaysInDisk) {
  Pcg32 rng(1, 1);
  for (int i = 0; i < 100000; ++i) {
    const Vec2f d = sample_concentric_disk(Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_LE(d.x * d.x + d.y * d.y, 1.0f + 1e-6f);
  }
}

// The polynomial cosine and sine of the concentric map against libm in double, over a
// dense grid of t ∈ [−1, 1] and its ends. Bound: float rounding of Horner's rule on terms
// of magnitude ≤ 1 (about 5 roundings of 2^-24 each, < 3.5e-7 in the worst case, typically
// 1–2 ulp) plus the 1.8e-9 truncation (warps.h); 2.5e-7 is 4 ulp of 1.
TEST(Warps, QuarterPiCosSinMatchesLibm) {
  double worst = 0.0;
  for (int i = -100000; i <= 100000; ++i) {
    const float t = static_cast<float>(i) / 100000.0f;
    const CosSin cs = cos_sin_quarter_pi(t);
    const double x = std::numbers::pi / 4.0 * double(t);
    worst = std::max({worst, std::abs(double(cs.cos) - std::cos(x)), std::abs(double(cs.sin) - std::sin(x))});
  }
  EXPECT_LE(worst, 2.5e-7);
  EXPECT_EQ(cos_sin_quarter_pi(0.0f).sin, 0.0f);
  EXPECT_EQ(cos_sin_quarter_pi(0.0f).cos, 1.0f);
}

// The map against its definition (Shirley & Chiu: r and φ per wedge, cos/sin from libm),
// in all four wedges and on the diagonals.
TEST(Warps, ConcentricDiskMatchesTheDefinition) {
  Pcg32 rng(3, 5);
  for (int i = 0; i < 100000 + 17 * 17; ++i) {
    // a 17 × 17 grid first (its points include the diagonals |a| = |b|), then random points
    const Vec2f u = i < 17 * 17 ? Vec2f((i % 17) / 16.0f * 0x1.fffffep-1f, (i / 17) / 16.0f * 0x1.fffffep-1f)
                                : Vec2f(rng.next_float(), rng.next_float());
    if (u.x == 0.5f && u.y == 0.5f) continue;  // the centre: no angle
    const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
      r = a;
      phi = std::numbers::pi / 4.0 * (b / a);
    } else {
      r = b;
      phi = std::numbers::pi / 2.0 - std::numbers::pi / 4.0 * (a / b);
    }
    const Vec2f d = sample_concentric_disk(u);
    // float inputs a, b and the quotient carry ~1e-7 relative; 1e-6 absolute on the unit disk
    ASSERT_NEAR(d.x, r * std::cos(phi), 1e-6) << u.x << " " << u.y;
    ASSERT_NEAR(d.y, r * std::sin(phi), 1e-6) << u.x << " " << u.y;
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
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kWarpChiSquareTests)) << r.message;
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
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kWarpChiSquareTests)) << r.message;
}

// Heitz (2019): the half u.x < u.y is sheared onto b2 > b1 by (u.x/2, u.y − u.x/2), the
// other half onto b1 ≥ b2 by (u.x − u.y/2, u.y/2). Exact in float for these dyadic inputs.
TEST(Warps, UniformTriangleIsHeitzLowDistortionMap) {
  const auto expect_map = [](Vec2f u, Vec2f b) {
    const Vec2f got = sample_uniform_triangle(u);
    EXPECT_EQ(got.x, b.x) << u.x << ", " << u.y;
    EXPECT_EQ(got.y, b.y) << u.x << ", " << u.y;
  };
  expect_map(Vec2f(0.25f, 0.75f), Vec2f(0.125f, 0.625f));
  expect_map(Vec2f(0.75f, 0.25f), Vec2f(0.625f, 0.125f));
  expect_map(Vec2f(0.5f, 0.5f), Vec2f(0.25f, 0.25f));
  expect_map(Vec2f(0.0f, 0.0f), Vec2f(0.0f, 0.0f));
  // Low distortion: points 1/64 apart in the square stay within a small multiple of that
  // on the triangle (the square-root map stretches them without bound near u.x = 0).
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const Vec2f a = sample_uniform_triangle(Vec2f(i / 64.0f, j / 64.0f));
      const Vec2f b = sample_uniform_triangle(Vec2f((i + 1) / 64.0f * 0.999f, j / 64.0f));
      EXPECT_LT(std::abs(a.x - b.x) + std::abs(a.y - b.y), 2.0f / 64.0f) << i << ", " << j;
    }
  // The branch-free form is Heitz's two-case form bit for bit, for every u the samplers
  // make (24-bit fractions: bits_to_unit_float), ties and the edges included.
  const auto two_case = [](Vec2f u) {
    return u.x < u.y ? Vec2f(0.5f * u.x, u.y - 0.5f * u.x) : Vec2f(u.x - 0.5f * u.y, 0.5f * u.y);
  };
  Pcg32 rng(3u, 5u);
  for (int k = 0; k < 200000; ++k) {
    const std::uint32_t bx = rng.next_u32(), by = k % 4 == 0 ? bx : rng.next_u32();
    const Vec2f u(static_cast<float>(bx >> 8) * 0x1p-24f, static_cast<float>(by >> 8) * 0x1p-24f);
    const Vec2f got = sample_uniform_triangle(u), want = two_case(u);
    ASSERT_EQ(std::bit_cast<std::uint32_t>(got.x), std::bit_cast<std::uint32_t>(want.x)) << u.x << ", " << u.y;
    ASSERT_EQ(std::bit_cast<std::uint32_t>(got.y), std::bit_cast<std::uint32_t>(want.y)) << u.x << ", " << u.y;
  }
  const Vec2f top = sample_uniform_triangle(Vec2f(0x1.fffffep-1f, 0x1.fffffep-1f));
  EXPECT_EQ(top.x, 0.5f * 0x1.fffffep-1f);
  EXPECT_EQ(top.y, 0.5f * 0x1.fffffep-1f);
}

// The wedge choice made with masked selects gives the branching form's points bit for bit.
TEST(Warps, ConcentricDiskSelectsMatchTheWedgeBranches) {
  const auto branching = [](Vec2f u) {
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return Vec2f(0.0f, 0.0f);
    const bool wedge_a = std::abs(a) > std::abs(b);
    const float r = wedge_a ? a : b;
    const CosSin cs = cos_sin_quarter_pi((wedge_a ? b : a) / r);
    const float along = r * cs.cos, across = r * cs.sin;
    return wedge_a ? Vec2f(along, across) : Vec2f(across, along);
  };
  Pcg32 rng(9u, 2u);
  for (int k = 0; k < 200000; ++k) {
    const float x = static_cast<float>(rng.next_u32() >> 8) * 0x1p-24f;
    // Every fourth point on a diagonal |a| = |b|, where the wedges meet.
    const float y = k % 4 == 0 ? (k % 8 == 0 ? x : 1.0f - x) : static_cast<float>(rng.next_u32() >> 8) * 0x1p-24f;
    const Vec2f got = sample_concentric_disk(Vec2f(x, y)), want = branching(Vec2f(x, y));
    ASSERT_EQ(std::bit_cast<std::uint32_t>(got.x), std::bit_cast<std::uint32_t>(want.x)) << x << ", " << y;
    ASSERT_EQ(std::bit_cast<std::uint32_t>(got.y), std::bit_cast<std::uint32_t>(want.y)) << x << ", " << y;
  }
}

TEST(Warps, PowerHeuristic) {
  EXPECT_FLOAT_EQ(power_heuristic(1.0f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(power_heuristic(3.0f, 1.0f), 0.9f);
  EXPECT_FLOAT_EQ(power_heuristic(0.0f, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(power_heuristic(2.0f, 5.0f) + power_heuristic(5.0f, 2.0f), 1.0f);
}

}  // namespace
}  // namespace prism
