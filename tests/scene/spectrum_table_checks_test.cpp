// The one set of rules for spectra given as scene data (scene/spectrum_table_checks.h),
// which the JSON and pbrt-v4 loaders and validate_scene all apply: each rule by a table
// that breaks it alone, with the message the user sees.
#include "prism/scene/spectrum_table_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace prism {
namespace {

std::string problem(const std::vector<double>& nm, const std::vector<double>& values, double max_value = 1.0) {
  return spectrum_table_problem(nm, values, max_value);
}

TEST(SpectrumTableChecks, AGoodTablePasses) {
  EXPECT_EQ(problem({380, 500, 780}, {0.0, 0.5, 1.0}), "");
  EXPECT_EQ(problem({100, 3000}, {7.0, 2e6}, kNoSpectrumMaximum), "");  // emitters have no maximum
}

TEST(SpectrumTableChecks, EachRuleHasItsMessage) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(problem({400, 500}, {0.5}), "2 wavelengths but 1 values");
  EXPECT_EQ(problem({400}, {0.5}), "a tabulated spectrum needs at least 2 points");
  EXPECT_EQ(problem({}, {}), "a tabulated spectrum needs at least 2 points");
  const std::vector<double> many(kMaxSpectrumPoints + 1, 0.5);
  EXPECT_EQ(problem(many, many), "more than 100000 points");
  EXPECT_EQ(problem({50, 500}, {0.5, 0.5}), "wavelength 50 nm is outside [100, 3000] nm");
  EXPECT_EQ(problem({400, 5000}, {0.5, 0.5}), "wavelength 5000 nm is outside [100, 3000] nm");
  EXPECT_EQ(problem({400, nan}, {0.5, 0.5}), "wavelength nan nm is outside [100, 3000] nm");
  EXPECT_EQ(problem({510, 500}, {0.5, 0.5}), "wavelengths must increase: 500 nm follows 510 nm");
  EXPECT_EQ(problem({500, 500}, {0.5, 0.5}), "wavelengths must increase: 500 nm follows 500 nm");
  EXPECT_EQ(problem({400, 500}, {0.5, -1}), "negative value -1 at 500 nm");
  EXPECT_EQ(problem({400, 500}, {nan, 0.5}, kNoSpectrumMaximum), "non-finite value nan at 400 nm");
  EXPECT_EQ(problem({400, 500}, {inf, 0.5}, kNoSpectrumMaximum), "non-finite value inf at 400 nm");
  EXPECT_EQ(problem({400, 500}, {0.5, 1.5}),
            "reflectance 1.5 at 500 nm is above 1 (a surface cannot reflect more than it receives)");
}

}  // namespace
}  // namespace prism
