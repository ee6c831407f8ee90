#include "prism/core/branch_free.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

#include "prism/core/pcg32.h"

namespace prism {
namespace {

constexpr float kNanF = std::numeric_limits<float>::quiet_NaN();
constexpr double kNanD = std::numeric_limits<double>::quiet_NaN();

TEST(BranchFree, SelectLessIsTheTernaryIncludingTiesSignedZerosAndNaN) {
  const float xs[] = {-1.0f, -0.0f, 0.0f, 0.5f, 1.0f, std::numeric_limits<float>::infinity(), kNanF};
  for (float x : xs)
    for (float y : xs) {
      // The chosen value is returned bit for bit (−0 stays −0).
      const float f = select_less(x, y, -0.0f, 3.5f);
      EXPECT_EQ(std::signbit(f), x < y) << x << " " << y;
      EXPECT_EQ(f, x < y ? -0.0f : 3.5f) << x << " " << y;
      const double d = select_less(double(x), double(y), -0.0, 3.5);
      EXPECT_EQ(std::signbit(d), x < y) << x << " " << y;
      EXPECT_EQ(d, x < y ? -0.0 : 3.5) << x << " " << y;
    }
  // A NaN value is passed through, not compared.
  EXPECT_TRUE(std::isnan(select_less(0.0f, 1.0f, kNanF, 2.0f)));
  EXPECT_EQ(select_less(1.0f, 0.0f, kNanF, 2.0f), 2.0f);
  EXPECT_TRUE(std::isnan(select_less(0.0, 1.0, kNanD, 2.0)));
}

TEST(BranchFree, KeepIfPassesTheValueBitForBitOrGivesPositiveZero) {
  const float values[] = {1.5f, -2.0f, -0.0f, 0.0f, std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::denorm_min(), kNanF};
  for (float v : values) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(keep_if(true, v)), std::bit_cast<std::uint32_t>(v)) << v;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(keep_if(false, v)), 0u) << v;  // +0, whatever v was
  }
}

std::size_t reference_upper_bound(const std::vector<float>& v, float x) {
  return static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), x) - v.begin());
}

TEST(BranchFree, UpperBoundIndexIsStdUpperBoundForEverySizeAndProbe) {
  Pcg32 rng(7u, 11u);
  for (std::size_t n = 0; n <= 70; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      // Few distinct values, so that runs of equal elements (zero-mass CDF cells) occur.
      std::vector<float> v(n);
      for (float& e : v) e = static_cast<float>(rng.next_u32() % 8u) * 0.125f;
      std::sort(v.begin(), v.end());
      std::vector<float> probes = {-1.0f, 0.0f, 1.0f, 2.0f, kNanF, -0.0f};
      for (float e : v) {
        probes.push_back(e);
        probes.push_back(std::nextafter(e, -2.0f));
        probes.push_back(std::nextafter(e, 2.0f));
      }
      for (int k = 0; k < 8; ++k) probes.push_back(rng.next_float());
      for (float x : probes)
        ASSERT_EQ(upper_bound_index(v.data(), v.size(), x), reference_upper_bound(v, x))
            << "n " << n << " x " << x;
    }
  }
}

}  // namespace
}  // namespace prism
