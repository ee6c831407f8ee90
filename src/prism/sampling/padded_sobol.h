#pragma once
// The keys of the padded Owen-scrambled Sobol' sampler (pixel_sampler.h, "sobol"; Burley
// 2020), in one place for its scalar form (pixel_sampler.cpp) and its AVX2 form
// (padded_sobol_lanes.h), which must draw the same bits.
//
// Every request (seed, pixel, sample, dimension) has one 64-bit hash: its low half seeds
// the nested uniform shuffle of the sample index, its high half the Owen scramble of the
// first axis, and the high half of its rehash that of the second axis (2D requests).
//
// By definition index = NUS(sample_index, low), x = NUS(sobol_0(index), high) and
// y = NUS(sobol_1(index), high'), with NUS(v, s) = rev(LK(rev(v), s)) (owen_scrambling.h).
// Since sobol_0 is rev itself, the reversals cancel: x = rev(LK(index, high)); the sample
// index is reversed once per block, and sobol_1 is taken already reversed. Three bit
// reversals per 2D request instead of seven, the same bits (pixel_sampler_test checks the
// definition).
#include <cstdint>

#include "prism/core/sample_stream.h"

namespace prism {

constexpr std::uint64_t padded_sobol_pixel_key(std::uint64_t seed, std::uint32_t pixel_index) {
  return mix64(mix64(seed ^ 0x736f626f6c5eedull) + pixel_index);
}

// What each dimension adds to the pixel key before hashing: 2^64 / φ (odd, so distinct
// dimensions give distinct keys).
inline constexpr std::uint64_t kPaddedSobolDimensionStep = 0x9e3779b97f4a7c15ull;

constexpr std::uint64_t padded_sobol_request_hash(std::uint64_t pixel_key, std::uint32_t dimension) {
  return mix64(pixel_key + kPaddedSobolDimensionStep * (dimension + 1ull));
}

// The seed of the index shuffle, of the first axis' scramble, and of the second axis'.
constexpr std::uint32_t padded_sobol_shuffle_seed(std::uint64_t request_hash) {
  return static_cast<std::uint32_t>(request_hash);
}
constexpr std::uint32_t padded_sobol_x_seed(std::uint64_t request_hash) {
  return static_cast<std::uint32_t>(request_hash >> 32);
}
constexpr std::uint32_t padded_sobol_y_seed(std::uint64_t request_hash) {
  return static_cast<std::uint32_t>(mix64(request_hash) >> 32);
}

}  // namespace prism
