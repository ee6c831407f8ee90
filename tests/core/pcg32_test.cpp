#include "prism/core/pcg32.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "prism/core/sample_stream.h"
#include "support/chi_square.h"

namespace prism {
namespace {

// Reference output of the PCG reference implementation's demo (pcg32-demo from
// pcg-c-basic): pcg32_srandom_r(&rng, 42u, 54u), then six pcg32_random_r calls.
TEST(Pcg32, MatchesReferenceImplementationOutput) {
  Pcg32 rng(42u, 54u);
  const std::array<std::uint32_t, 6> expected = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                                 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (std::uint32_t e : expected) EXPECT_EQ(rng.next_u32(), e);
}

TEST(Pcg32, FloatsAreInHalfOpenUnitInterval) {
  Pcg32 rng(1u, 2u);
  for (int i = 0; i < 100000; ++i) {
    const float f = rng.next_float();
    ASSERT_GE(f, 0.0f);
    ASSERT_LT(f, 1.0f);
    const double d = rng.next_double();
    ASSERT_GE(d, 0.0);
    ASSERT_LT(d, 1.0);
  }
}

// Uniformity of next_float by a chi-square test on 100 equal bins.
TEST(Pcg32, FloatsAreUniform) {
  Pcg32 rng(7u, 3u);
  constexpr int kBins = 100, kSamples = 1'000'000;
  std::vector<double> observed(kBins, 0.0), expected(kBins, double(kSamples) / kBins);
  for (int i = 0; i < kSamples; ++i) observed[static_cast<std::size_t>(rng.next_float() * kBins)] += 1.0;
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, 1e-3) << r.message;  // a false alarm once in a thousand seeds
}

TEST(Pcg32, BoundedIsUniformAndInRange) {
  Pcg32 rng(11u, 5u);
  constexpr std::uint32_t kBound = 7;
  constexpr int kSamples = 700'000;
  std::vector<double> observed(kBound, 0.0), expected(kBound, double(kSamples) / kBound);
  for (int i = 0; i < kSamples; ++i) {
    const std::uint32_t v = rng.next_bounded(kBound);
    ASSERT_LT(v, kBound);
    observed[v] += 1.0;
  }
  EXPECT_GT(test::chi_square_test(observed, expected).p_value, 1e-3);
}

TEST(SampleStream, DependsOnlyOnSeedPixelAndSampleIndex) {
  Pcg32 a = make_sample_stream(5, 1234, 17);
  Pcg32 b = make_sample_stream(5, 1234, 17);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(a.next_u32(), b.next_u32());
}

TEST(SampleStream, NeighbouringKeysGiveUnrelatedStreams) {
  // Adjacent pixels, samples and seeds must not produce shifted copies of one sequence:
  // compare the first outputs of many neighbouring keys for collisions.
  std::vector<std::uint32_t> firsts;
  for (std::uint64_t seed = 0; seed < 4; ++seed)
    for (std::uint64_t pixel = 0; pixel < 64; ++pixel)
      for (std::uint64_t s = 0; s < 64; ++s) firsts.push_back(make_sample_stream(seed, pixel, s).next_u32());
  std::sort(firsts.begin(), firsts.end());
  // 16384 draws from 2^32 values: the expected number of equal pairs is n²/2^33 ≈ 0.03.
  EXPECT_EQ(std::adjacent_find(firsts.begin(), firsts.end()), firsts.end());
}

}  // namespace
}  // namespace prism
