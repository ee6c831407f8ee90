// core/log4.h: four logarithms at once, against double-precision std::log, and its SSE2
// path and its eight AVX2 lanes against the lane-by-lane code they must match bit for bit.
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

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
[[gnu::target("avx2")]] std::array<float, 8> log8(const std::array<float, 8>& x) {
  std::array<float, 8> out;
  _mm256_storeu_ps(out.data(), log8_ps(_mm256_loadu_ps(x.data())));
  return out;
}

TEST(Log4, EightLanesMatchTheLanewiseCodeBitForBit) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this processor has no AVX2";
  const std::vector<float> x = inputs();
  for (std::size_t i = 0; i + 8 <= x.size(); i += 8) {
    const std::array<float, 8> out = log8({x[i], x[i + 1], x[i + 2], x[i + 3], x[i + 4], x[i + 5], x[i + 6], x[i + 7]});
    for (std::size_t half = 0; half < 2; ++half) {
      const std::array<float, 4> in{x[i + 4 * half], x[i + 4 * half + 1], x[i + 4 * half + 2], x[i + 4 * half + 3]};
      const std::array<float, 4> expected = log4_lanewise(in);
      for (std::size_t k = 0; k < 4; ++k) ASSERT_EQ(out[4 * half + k], expected[k]) << in[k];
    }
  }
}
#endif

}  // namespace
}  // namespace prism
