#pragma once
// Deterministic random stream per (seed, pixel, sample index). The numbers a sample sees
// depend only on these three values, never on which thread renders it or in what order,
// so an image is bitwise reproducible for any thread count.
#include <cstdint>

#include "prism/core/pcg32.h"

namespace prism {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mixer used to turn
// structured keys into well-distributed PCG seeds.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

constexpr Pcg32 make_sample_stream(std::uint64_t seed, std::uint64_t pixel_index,
                                   std::uint64_t sample_index) {
  const std::uint64_t key = mix64(mix64(seed ^ 0x9e3779b97f4a7c15ull) + pixel_index);
  return Pcg32(mix64(key + sample_index), key);
}

}  // namespace prism
