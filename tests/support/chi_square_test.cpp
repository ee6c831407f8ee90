#include "support/chi_square.h"

#include <gtest/gtest.h>

namespace prism::test {
namespace {

// Reference quantiles of the chi-square distribution (any statistics table, e.g.
// NIST/SEMATECH e-Handbook 1.3.6.7.4): P(X >= x) for the given dof.
TEST(ChiSquareHarness, SurvivalMatchesTables) {
  EXPECT_NEAR(chi_square_survival(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_survival(6.635, 1), 0.01, 1e-4);
  EXPECT_NEAR(chi_square_survival(18.307, 10), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_survival(124.342, 100), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_survival(0.0, 5), 1.0, 1e-12);
}

TEST(ChiSquareHarness, DetectsAWrongDistribution) {
  const std::vector<double> observed = {100, 100, 100, 700};
  const std::vector<double> expected = {250, 250, 250, 250};
  EXPECT_LT(chi_square_test(observed, expected).p_value, 1e-10);
}

TEST(ChiSquareHarness, FailsOnSamplesWhereThePdfIsZero) {
  const std::vector<double> observed = {10, 10, 1};
  const std::vector<double> expected = {10.5, 10.5, 0};
  EXPECT_EQ(chi_square_test(observed, expected).p_value, 0.0);
}

TEST(ChiSquareHarness, SidakCorrection) {
  EXPECT_NEAR(sidak_alpha(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(1.0 - std::pow(1.0 - sidak_alpha(0.01, 20), 20), 0.01, 1e-12);
}

}  // namespace
}  // namespace prism::test
