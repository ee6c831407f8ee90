#pragma once
// Pearson chi-square goodness-of-fit harness for sampling routines. Shape after the
// Mitsuba test suite: histogram the samples, integrate the pdf over the same bins, pool
// sparse bins, and judge with a significance level corrected for the number of tests
// (Šidák) so that a suite of many tests keeps an overall false-alarm rate.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "prism/core/vec.h"

namespace prism::test {

// Overall false-alarm rate that every chi-square test file splits over its own histograms
// (Šidák): one figure for all sampling tests, declared once so that the test files can
// share a translation unit (unity builds).
inline constexpr double kAlphaTotal = 0.01;

struct ChiSquareResult {
  double statistic = 0.0;
  int degrees_of_freedom = 0;
  double p_value = 1.0;
  std::string message;  // why it failed, for the test log
};

// Upper tail P(X >= x) of the chi-square distribution with `dof` degrees of freedom.
double chi_square_survival(double x, int dof);

// Significance level per test so that `test_count` independent tests together have
// false-alarm probability `alpha_total`: 1 - (1 - alpha)^(1/n) (Šidák 1967).
double sidak_alpha(double alpha_total, int test_count);

// Compares observed counts with expected counts. Bins whose expectation is below
// `min_expected` are pooled together (smallest first) until the pool reaches it.
// A bin with observations but (numerically) zero expectation fails outright.
ChiSquareResult chi_square_test(std::span<const double> observed,
                                std::span<const double> expected, double min_expected = 5.0);

// Histograms `sample_count` directions drawn by `sample` over a (cos θ, φ) grid covering
// the whole sphere and integrates `pdf` (solid-angle density) over each bin. Directions
// that `sample` reports as failed (returns false) count as absent mass. Each bin's pdf
// integral is a 2D Simpson rule with `simpson_intervals` (even) intervals per axis: ample
// for smooth densities; a density that jumps inside a bin (a lobe cut off along a curve)
// integrates only to O(1/intervals) there and needs more.
struct SphericalHistogram {
  std::vector<double> observed;
  std::vector<double> expected;
};
SphericalHistogram spherical_histogram(
    const std::function<bool(Vec2f u, Vec3f& direction)>& sample,
    const std::function<double(const Vec3f& direction)>& pdf, int cos_theta_bins, int phi_bins,
    long sample_count, unsigned long long seed, int simpson_intervals = 8);

}  // namespace prism::test
