#pragma once
// Hash-based Owen scrambling (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT
// 9(4); after Laine & Karras 2011, "Stratified sampling for stochastic transparency").
//
// Owen's nested uniform scrambling flips bit d of a point (d = 0 the most significant)
// with a random choice that depends only on the d bits above it. Laine and Karras note
// that, on the bit-reversed value, that is any function where each output bit depends on
// its own input bit (xor) plus lower bits only: adding a seed, and x ^= x·c for even c,
// have that property. Applied to a point it keeps every (0,m,2)-net a net and makes each
// point uniform over [0,1); applied to an index it permutes every aligned block of 2^m
// indices within itself (Burley §4, "shuffling").
#include <cstdint>

#include "prism/core/sample_stream.h"
#include "prism/sampling/sobol.h"

namespace prism {

// Burley 2020, listing 2 (his improved multipliers): bit k of the result depends on
// input bits 0..k only.
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Owen scrambling of a 32-bit fraction (or a nested permutation of an index).
constexpr std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
  return reverse_bits_32(laine_karras_permutation(reverse_bits_32(x), seed));
}

// 32-bit seed from structured keys (SplitMix64 finaliser chain): distinct keys give
// independent-looking seeds.
constexpr std::uint32_t hash_seed(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d) {
  return static_cast<std::uint32_t>(mix64(mix64(mix64(mix64(a ^ 0x5851f42d4c957f2dull) + b) + c) + d) >> 32);
}

}  // namespace prism
