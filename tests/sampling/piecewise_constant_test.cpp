#include "prism/sampling/piecewise_constant.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <vector>

#include "prism/core/error.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"
#include "support/chi_square.h"

namespace prism {
namespace {

constexpr int kPiecewiseChiSquareTests = 6;  // 1D continuous, 1D discrete, 2D, sphere, 2 cones
constexpr long kSamples = 200'000;

const std::vector<float> kF = {0.0f, 1.0f, 3.0f, 0.5f, 0.0f, 2.0f, 7.0f, 0.25f};

// Continuous samples histogrammed on 4 sub-bins per cell; expected mass pmf/4 each.
TEST(PiecewiseConstant, OneDimensionalContinuousMatchesPdf) {
  const PiecewiseConstant1D d(kF, -1.0f, 3.0f);
  EXPECT_NEAR(d.integral(), (0 + 1 + 3 + 0.5 + 0 + 2 + 7 + 0.25) * 0.5, 1e-5);
  constexpr int kSub = 4;
  std::vector<double> observed(kF.size() * kSub, 0.0), expected(observed.size(), 0.0);
  Pcg32 rng(1, 2);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = d.sample_continuous(rng.next_float());
    ASSERT_GE(s.x, -1.0f);
    ASSERT_LT(s.x, 3.0f);
    ASSERT_NEAR(s.pdf, d.pdf(s.x), 1e-5f);
    observed[std::min<std::size_t>(observed.size() - 1, static_cast<std::size_t>((s.x + 1.0f) / 4.0f * observed.size()))] += 1;
  }
  for (std::size_t i = 0; i < observed.size(); ++i) expected[i] = kSamples * d.pmf(static_cast<int>(i / kSub)) / kSub;
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kPiecewiseChiSquareTests)) << r.message;
}

TEST(PiecewiseConstant, OneDimensionalDiscreteMatchesPmf) {
  const PiecewiseConstant1D d(kF);
  std::vector<double> observed(kF.size(), 0.0), expected(kF.size(), 0.0);
  Pcg32 rng(3, 4);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = d.sample_discrete(rng.next_float());
    ASSERT_GT(s.pmf, 0.0f);
    ASSERT_GE(s.u_remapped, 0.0f);
    ASSERT_LT(s.u_remapped, 1.0f);
    observed[s.index] += 1;
  }
  for (std::size_t i = 0; i < kF.size(); ++i) expected[i] = kSamples * d.pmf(static_cast<int>(i));
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kPiecewiseChiSquareTests)) << r.message;
}

// A guide table must find exactly the cells the binary search finds: for random u, for u
// at and just below/above every CDF step (where an off-by-one would show) and every guide
// entry's boundary g / G, across zero-mass cells and runs of them, and at 0 and 1;
// sample_continuous then agrees bit for bit. The fine table (build_guide_table) also with a
// tiny cell, where it needs more entries than 4 per cell; the coarse one
// (build_coarse_guide_table, environment-map rows) on sizes that are not a multiple of its
// entry spacing and on a long row with a spike and long dark runs, where a bracket spans
// many cells.
std::vector<std::vector<float>> guide_test_distributions() {
  std::vector<float> tiny = kF;
  tiny[3] = 1e-6f;
  std::vector<float> row(1000);
  Pcg32 rng(11, 12);
  for (std::size_t i = 0; i < row.size(); ++i) row[i] = (i / 100) % 3 == 1 ? 0.0f : rng.next_float();
  row[517] = 5000.0f;  // a sun
  std::vector<float> nine = {1, 0, 2, 0, 0, 3, 1, 1, 4};
  return {kF, tiny, std::vector<float>{2.0f}, nine, row};
}

void expect_same_cells(const PiecewiseConstant1D& searched, const PiecewiseConstant1D& guided, int guide_entries) {
  std::vector<float> us = {0.0f, 1.0f, std::nextafter(1.0f, 0.0f), 0.5f};
  for (int i = 0; i <= searched.size(); ++i) {
    const float c = searched.cdf(i);
    us.insert(us.end(), {c, std::nextafter(c, 0.0f), std::nextafter(c, 1.0f)});
  }
  for (int g = 0; g <= guide_entries; ++g) {
    const float b = static_cast<float>(g) / static_cast<float>(guide_entries);
    us.insert(us.end(), {b, std::nextafter(b, 0.0f), std::nextafter(b, 1.0f)});
  }
  Pcg32 rng(5, 6);
  for (int i = 0; i < 100000; ++i) us.push_back(rng.next_float());
  for (const float u : us) {
    if (u < 0.0f || u > 1.0f) continue;
    const auto a = searched.sample_continuous(u), b = guided.sample_continuous(u);
    ASSERT_EQ(a.index, b.index) << u;
    ASSERT_EQ(a.x, b.x) << u;
    ASSERT_EQ(a.pdf, b.pdf) << u;
    ASSERT_EQ(searched.sample_discrete(u).index, guided.sample_discrete(u).index) << u;
  }
}

TEST(PiecewiseConstant, GuideTableFindsTheSameCellsAsTheSearch) {
  for (const std::vector<float>& f : guide_test_distributions()) {
    const PiecewiseConstant1D searched(f, 380.0f, 780.0f);
    PiecewiseConstant1D guided = searched;
    guided.build_guide_table();
    expect_same_cells(searched, guided, 4 * searched.size());
  }
}

TEST(PiecewiseConstant, CoarseGuideTableFindsTheSameCellsAsTheSearch) {
  for (const std::vector<float>& f : guide_test_distributions()) {
    const PiecewiseConstant1D searched(f, 380.0f, 780.0f);
    PiecewiseConstant1D guided = searched;
    guided.build_coarse_guide_table();
    const int per_entry = PiecewiseConstant1D::kCellsPerCoarseGuideEntry;
    const auto cells = static_cast<unsigned>((searched.size() + per_entry - 1) / per_entry);
    const int entries = static_cast<int>(std::bit_ceil(cells));
    expect_same_cells(searched, guided, entries);
  }
}

TEST(PiecewiseConstant, DegenerateAndInvalidInputs) {
  const std::vector<float> zeros(5, 0.0f);
  const PiecewiseConstant1D u(zeros);
  EXPECT_FLOAT_EQ(u.pdf(0.3f), 1.0f);  // all-zero: uniform
  EXPECT_THROW(PiecewiseConstant1D(std::vector<float>{1.0f, -1.0f}), UsageError);
  EXPECT_THROW(PiecewiseConstant1D(std::vector<float>{}), UsageError);
  EXPECT_THROW(PiecewiseConstant1D(std::vector<float>{NAN}), UsageError);
  EXPECT_THROW(PiecewiseConstant2D(kF, 3, 3), UsageError);
}

// 2D: a 6 × 4 grid; histogram on the cells themselves (the density is constant in each).
TEST(PiecewiseConstant, TwoDimensionalMatchesPdf) {
  const int nu = 6, nv = 4;
  std::vector<float> f(nu * nv);
  for (int i = 0; i < nu * nv; ++i) f[i] = static_cast<float>((i * 7) % 5);  // includes zeros
  const PiecewiseConstant2D d(f, nu, nv);
  double total = 0;
  for (float v : f) total += v;
  std::vector<double> observed(f.size(), 0.0), expected(f.size(), 0.0);
  Pcg32 rng(5, 6);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = d.sample(Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_NEAR(s.pdf, d.pdf(s.p), 1e-4f * s.pdf);
    const int iu = std::min(nu - 1, static_cast<int>(s.p.x * nu)), iv = std::min(nv - 1, static_cast<int>(s.p.y * nv));
    observed[iv * nu + iu] += 1;
  }
  for (std::size_t i = 0; i < f.size(); ++i) expected[i] = kSamples * f[i] / total;
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kPiecewiseChiSquareTests)) << r.message;
  EXPECT_NEAR(d.pdf(Vec2f(0.01f, 0.01f)), f[0] / total * nu * nv, 1e-4);
}

// Built row by row (what environment maps use, so that their grid of weights never exists
// whole), the distribution is the grid constructor's, bit for bit; rows are asked for once
// each, in order (the light sampler accumulates its mean radiance in that order).
TEST(PiecewiseConstant, TwoDimensionalRowByRowIsTheGridsDistribution) {
  const int nu = 7, nv = 5;
  std::vector<float> f(nu * nv);
  for (int i = 0; i < nu * nv; ++i) f[i] = static_cast<float>((i * 11) % 6) * 0.3f;
  std::vector<int> rows_asked;
  const PiecewiseConstant2D rows(nu, nv, [&](int v, std::span<float> row) {
    rows_asked.push_back(v);
    ASSERT_EQ(row.size(), static_cast<std::size_t>(nu));
    std::copy(f.begin() + v * nu, f.begin() + (v + 1) * nu, row.begin());
  });
  EXPECT_EQ(rows_asked, (std::vector<int>{0, 1, 2, 3, 4}));
  const PiecewiseConstant2D grid(f, nu, nv);
  EXPECT_EQ(rows.integral(), grid.integral());
  Pcg32 rng(9, 2);
  for (int i = 0; i < 1000; ++i) {
    const Vec2f u(rng.next_float(), rng.next_float());
    const auto a = rows.sample(u), b = grid.sample(u);
    ASSERT_EQ(a.p.x, b.p.x);
    ASSERT_EQ(a.p.y, b.p.y);
    ASSERT_EQ(a.pdf, b.pdf);
    ASSERT_EQ(rows.pdf(u), grid.pdf(u));
  }
  EXPECT_THROW(PiecewiseConstant2D(0, 3, [](int, std::span<float>) {}), UsageError);
}

TEST(Warps, UniformSphereMatchesItsPdf) {
  const auto h = test::spherical_histogram(
      [](Vec2f u, Vec3f& d) {
        d = sample_uniform_sphere(u);
        return true;
      },
      [](const Vec3f&) { return double(uniform_sphere_pdf()); }, 20, 40, kSamples, 7);
  const auto r = test::chi_square_test(h.observed, h.expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kPiecewiseChiSquareTests)) << r.message;
}

// Cones of half-angle 60° and 0.27° (the Sun's angular radius). The density is uniform
// in (cos θ, φ) over [cos θmax, 1] × [0, 2π), so each cell of a 20 × 20 grid over that
// domain expects exactly 1/400 of the samples: no quadrature (the harness's Simpson rule
// would straddle the cone's edge), and the narrow cone is resolved as well as the broad.
TEST(Warps, UniformConeMatchesItsPdf) {
  for (double deg : {60.0, 0.27}) {
    const double cos_max = std::cos(deg * std::numbers::pi / 180.0);
    const float cos_max_f = static_cast<float>(cos_max);
    EXPECT_NEAR(uniform_cone_pdf(cos_max_f) * 2.0 * std::numbers::pi * (1.0 - cos_max_f), 1.0, 1e-5);
    constexpr int kBins = 20;
    std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, double(kSamples) / (kBins * kBins));
    Pcg32 rng(8, 9);
    for (long i = 0; i < kSamples; ++i) {
      const Vec3f d = sample_uniform_cone(Vec2f(rng.next_float(), rng.next_float()), cos_max_f);
      ASSERT_NEAR(length(d), 1.0f, 1e-5f);
      ASSERT_GE(d.z, cos_max_f - 1e-6f);
      // Recover cos θ from the sine for accuracy near the pole: 1 − cos θ = sin²θ/(1 + cos θ).
      const double sin2 = double(d.x) * d.x + double(d.y) * d.y;
      const double one_minus_cos = sin2 / (1.0 + d.z);
      double phi = std::atan2(double(d.y), double(d.x));
      if (phi < 0) phi += 2.0 * std::numbers::pi;
      const int ic = std::clamp(static_cast<int>(one_minus_cos / (1.0 - cos_max) * kBins), 0, kBins - 1);
      const int ip = std::min(kBins - 1, static_cast<int>(phi / (2.0 * std::numbers::pi) * kBins));
      observed[ic * kBins + ip] += 1;
    }
    const auto r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kPiecewiseChiSquareTests)) << deg << "°: " << r.message;
  }
}

}  // namespace
}  // namespace prism
