// core/log4.h: four logarithms at once, against double-precision std::log, and its SSE2
// path against the lane-by-lane code it must match bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "prism/core/log4.h"

namespace prism {
namespace {

// Log-spaced inputs over [2^-10, 2^10] (the callers need [0.05, 40]), mantissas next to
// the √2 split, and exact powers of two.
std::vector<float> inputs() {
  std::vector<float> x;
  for (int i = 0; i <= 400'000; ++i) x.push_back(static_cast<float>(std::exp2(-10.0 + 20.0 * i / 400'000.0)));
  for (int e = -10; e <= 10; ++e)
    for (float m : {1.0f, std::nextafter(1.41421356f, 0.0f), 1.41421356f, std::nextafter(1.41421356f, 2.0f),
                    std::nextafter(2.0f, 0.0f)})
      x.push_back(std::ldexp(m, e));
  return x;
}

// The bound: float rounding of ln m (|ln m| ≤ ½ ln 2; s, the series and the product each
// round within an ulp or two: 4 ulp of 0.35 is 1.7e-7, here 2e-7 with margin), of e·ln 2
// (kLn2 is within ½ ulp of ln 2, 3e-8 per unit of e) and of the final sum (½ ulp of the
// result). The series' truncation, < 7e-10, is below all of them.
TEST(Log4, MatchesDoubleLogToFloatRounding) {
  const std::vector<float> x = inputs();
  double worst = 0.0;
  for (std::size_t i = 0; i + 4 <= x.size(); i += 4) {
    const std::array<float, 4> in{x[i], x[i + 1], x[i + 2], x[i + 3]};
    const std::array<float, 4> out = log4(in);
    for (std::size_t k = 0; k < 4; ++k) {
      const double exact = std::log(double(in[k]));
      const double e = std::abs(std::round(exact / std::log(2.0)));
      const double bound = 2e-7 + 3e-8 * e + 0x1p-24 * std::abs(exact);
      ASSERT_NEAR(out[k], exact, bound) << in[k];
      worst = std::max(worst, std::abs(out[k] - exact) / bound);
    }
  }
  std::printf("[ log4 ] worst error %.3f of the bound\n", worst);
}

TEST(Log4, VectorPathMatchesTheLanewiseCodeBitForBit) {
  const std::vector<float> x = inputs();
  for (std::size_t i = 0; i + 4 <= x.size(); i += 4) {
    const std::array<float, 4> in{x[i], x[i + 1], x[i + 2], x[i + 3]};
    const std::array<float, 4> a = log4(in), b = log4_lanewise(in);
    for (std::size_t k = 0; k < 4; ++k) ASSERT_EQ(a[k], b[k]) << in[k];
  }
}

}  // namespace
}  // namespace prism
