#pragma once
// Tolerances and a matrix check for tests against published colour matrices (the colour-space
// and chromatic-adaptation tests share them; one definition lets those files share a
// translation unit in a unity build).
#include <gtest/gtest.h>

#include "prism/core/mat3.h"

namespace prism::test {

// A value published to n decimals is matched to half a unit of its last digit (the
// derivations are exact to ~1e-16, so all of that margin is the publication's rounding).
// Values that are exact rationals, or properties that hold exactly in real arithmetic, are
// matched to 1e-12: a few dozen double roundings on O(1) numbers.
inline constexpr double kHalf7 = 0.5e-7;
inline constexpr double kHalf10 = 0.5e-10;
inline constexpr double kExact = 1e-12;

// Every element of `actual` within `tol` of the published `expected` (row-major).
inline void expect_matrix_near(const Mat3& actual, const double (&expected)[3][3], double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(actual(i, j), expected[i][j], tol) << "element " << i << "," << j;
}

}  // namespace prism::test
