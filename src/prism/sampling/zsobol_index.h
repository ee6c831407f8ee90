#pragma once
// Blue-noise ordering of pixels (Ahmed & Wonka 2020, "Screen-space blue-noise diffusion of
// Monte Carlo sampling error via hierarchical ordering of pixels", SIGGRAPH Asia; as
// described for pbrt-v4's ZSobolSampler): pixels are numbered along the Morton (Z) curve,
// and every base-4 digit of that number goes through a random permutation of {0,1,2,3}
// chosen by a hash of the digits above it. Every aligned 2^k × 2^k tile of pixels then
// owns an aligned block of 4^k indices, so the tile's points of one Sobol' (0,2)-sequence
// form a (0,2k,2)-net — neighbouring pixels get well-separated numbers, which pushes the
// image error to high frequencies — while the permutations keep the pattern from repeating.
#include <algorithm>
#include <array>
#include <cstdint>

#include "prism/core/sample_stream.h"

namespace prism {

// Interleaves x (even bits) and y (odd bits); x, y < 2^16.
constexpr std::uint32_t morton_index_2d(std::uint32_t x, std::uint32_t y) {
  const auto spread = [](std::uint32_t v) {
    v &= 0xffffu;
    v = (v | (v << 8)) & 0x00ff00ffu;
    v = (v | (v << 4)) & 0x0f0f0f0fu;
    v = (v | (v << 2)) & 0x33333333u;
    return (v | (v << 1)) & 0x55555555u;
  };
  return spread(x) | (spread(y) << 1);
}

// All 24 permutations of {0, 1, 2, 3}, in lexicographic order.
constexpr std::array<std::array<std::uint8_t, 4>, 24> base4_digit_permutations() {
  std::array<std::array<std::uint8_t, 4>, 24> table{};
  std::array<std::uint8_t, 4> p{0, 1, 2, 3};
  for (auto& row : table) {
    row = p;
    std::next_permutation(p.begin(), p.end());
  }
  return table;
}

// A cheap 32-bit integer hash (Wellons' "lowbias32" finaliser) for the per-digit choices.
constexpr std::uint32_t hash_digit_prefix(std::uint32_t prefix, std::uint32_t seed) {
  std::uint32_t x = prefix * 0x9e3779b1u ^ seed;
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  return x ^ (x >> 16);
}

// Permutes the base-4 digits of `index`, each by a permutation chosen from a hash of
// `seed` and the (unpermuted) digits above it: a bijection that maps every aligned block
// of 4^k indices onto an aligned block of 4^k indices. Digits whose prefix is all zero
// (above the index's leading digit, and the leading digit itself when its prefix is
// zero) take the identity permutation, a fixed member of the family: the map stays a
// nested digit permutation, and the loop only runs over the digits an image uses.
constexpr std::uint32_t permute_base4_digits(std::uint32_t index, std::uint32_t seed) {
  constexpr auto kPermutations = base4_digit_permutations();
  std::uint32_t result = 0;
  for (int shift = 0; shift < 32; shift += 2) {
    const std::uint32_t higher = shift + 2 < 32 ? index >> (shift + 2) : 0u;
    const std::uint32_t digit = (index >> shift) & 3u;
    if (higher == 0) return result | (digit << shift);  // identity from here up
    // Multiply-shift maps the hash's top bits onto 0..23 without a division.
    const auto choice = static_cast<std::size_t>((std::uint64_t{hash_digit_prefix(higher, seed)} * 24u) >> 32);
    result |= std::uint32_t{kPermutations[choice][digit]} << shift;
  }
  return result;
}

}  // namespace prism
