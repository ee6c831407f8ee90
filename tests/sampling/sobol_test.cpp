// Sobol' dimensions 0 and 1: published first points and direction numbers, and the
// (0,m,2)-net property of aligned blocks, unscrambled and Owen-scrambled.
#include "prism/sampling/sobol.h"

#include <gtest/gtest.h>

#include <vector>

#include "prism/sampling/owen_scrambling.h"

namespace prism {
namespace {

double unit(std::uint32_t bits) { return bits * 0x1p-32; }

TEST(Sobol, FirstPointsAreTheKnownSequence) {
  // Natural (not Gray-code) order: dimension 0 is van der Corput's radical inverse.
  const double dim0[] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double dim1[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (std::uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(unit(sobol_sample_bits(i, 0)), dim0[i]) << i;
    EXPECT_EQ(unit(sobol_sample_bits(i, 1)), dim1[i]) << i;
  }
}

TEST(Sobol, FastProductsEqualTheMatrixProduct) {
  for (int dimension : {0, 1}) {
    const auto columns = sobol_generator_matrix(dimension);
    for (std::uint32_t i : {0u, 1u, 6u, 255u, 256u, 0x80000001u, 0xdeadbeefu, 0xffffffffu}) {
      std::uint32_t x = 0;
      for (int j = 0; j < 32; ++j)
        if ((i >> j) & 1u) x ^= columns[static_cast<std::size_t>(j)];
      EXPECT_EQ(sobol_sample_bits(i, dimension), x) << "dim " << dimension << " index " << i;
    }
  }
}

TEST(Sobol, ReversedDimensionOneIsTheReversedProduct) {
  for (std::uint32_t i : {0u, 1u, 6u, 255u, 256u, 0x80000001u, 0xdeadbeefu, 0xffffffffu})
    EXPECT_EQ(sobol_dimension1_reversed_bits(i), reverse_bits_32(sobol_sample_bits(i, 1))) << i;
  std::uint32_t i = 12345u;
  for (int k = 0; k < 1000; ++k, i = i * 747796405u + 2891336453u)
    ASSERT_EQ(sobol_dimension1_reversed_bits(i), reverse_bits_32(sobol_sample_bits(i, 1))) << i;
}

TEST(Sobol, DirectionNumbersOfDimensionOneMatchJoeKuo) {
  // Joe & Kuo (2008) list m = 1, 3, 5, 15, 17, 51, 85, 255 for their second dimension
  // (polynomial x + 1); the derived matrix must hold m_j · 2^(31-j).
  const std::uint32_t m[] = {1, 3, 5, 15, 17, 51, 85, 255};
  const auto columns = sobol_generator_matrix(1);
  for (int j = 0; j < 8; ++j) EXPECT_EQ(columns[static_cast<std::size_t>(j)], m[j] << (31 - j)) << j;
  // Every m_j is odd: C is upper triangular with a unit diagonal, hence invertible.
  for (int j = 0; j < 32; ++j) EXPECT_EQ((columns[static_cast<std::size_t>(j)] >> (31 - j)) & 1u, 1u) << j;
}

// Every elementary interval [a/2^k, (a+1)/2^k) × [b/2^(m-k), (b+1)/2^(m-k)) holds exactly
// one of the 2^m points, for every k = 0..m.
bool is_zero_m_2_net(const std::vector<std::uint32_t>& x, const std::vector<std::uint32_t>& y, int m) {
  const std::size_t n = std::size_t{1} << m;
  if (x.size() != n || y.size() != n) return false;
  for (int k = 0; k <= m; ++k) {
    std::vector<int> count(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t a = k == 0 ? 0 : x[i] >> (32 - k);
      const std::uint64_t b = m - k == 0 ? 0 : y[i] >> (32 - (m - k));
      if (++count[(a << (m - k)) | b] > 1) return false;
    }
  }
  return true;
}

TEST(Sobol, AlignedBlocksAreZeroM2Nets) {
  for (int m = 0; m <= 10; ++m)
    for (std::uint32_t block : {0u, 1u, 7u, 1000u}) {
      std::vector<std::uint32_t> x, y;
      for (std::uint32_t i = 0; i < (1u << m); ++i) {
        x.push_back(sobol_sample_bits((block << m) + i, 0));
        y.push_back(sobol_sample_bits((block << m) + i, 1));
      }
      EXPECT_TRUE(is_zero_m_2_net(x, y, m)) << "m " << m << " block " << block;
    }
}

TEST(Sobol, OwenScrambledAndShuffledPrefixesAreZeroM2Nets) {
  // Scrambling the points (Owen) and shuffling the index (a nested permutation that keeps
  // aligned blocks) must both keep the net property, for any seeds.
  for (std::uint32_t seed = 0; seed < 8; ++seed)
    for (int m = 1; m <= 10; ++m) {
      const std::uint32_t sx = hash_seed(seed, 1, m, 0), sy = hash_seed(seed, 2, m, 0), si = hash_seed(seed, 3, m, 0);
      std::vector<std::uint32_t> x, y;
      for (std::uint32_t i = 0; i < (1u << m); ++i) {
        const std::uint32_t index = nested_uniform_scramble(i, si);
        x.push_back(nested_uniform_scramble(sobol_sample_bits(index, 0), sx));
        y.push_back(nested_uniform_scramble(sobol_sample_bits(index, 1), sy));
      }
      EXPECT_TRUE(is_zero_m_2_net(x, y, m)) << "seed " << seed << " m " << m;
    }
}

TEST(Sobol, IndexShuffleIsAPermutationOfEveryAlignedBlock) {
  for (std::uint32_t seed : {1u, 0xdeadbeefu}) {
    std::vector<int> seen(1024, 0);
    for (std::uint32_t i = 0; i < 1024; ++i) {
      const std::uint32_t j = nested_uniform_scramble(i, seed);
      EXPECT_EQ(j >> 10, nested_uniform_scramble(0, seed) >> 10) << "left the aligned block";
      ++seen[j & 1023u];
    }
    for (int c : seen) EXPECT_EQ(c, 1);
  }
}

}  // namespace
}  // namespace prism
