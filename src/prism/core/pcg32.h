#pragma once
// PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation"): 64-bit LCG state, XSH-RR output to 32 bits.
#include <cstdint>

namespace prism {

class Pcg32 {
 public:
  static constexpr std::uint64_t kMultiplier = 6364136223846793005ull;
  static constexpr std::uint64_t kDefaultState = 0x853c49e6748fea9bull;
  static constexpr std::uint64_t kDefaultStream = 0xda3e39cb94b95bdbull;

  constexpr Pcg32() = default;
  constexpr Pcg32(std::uint64_t seed, std::uint64_t stream) { seed_stream(seed, stream); }

  // The reference initialisation of pcg32_srandom_r, so outputs match the published demo.
  constexpr void seed_stream(std::uint64_t seed, std::uint64_t stream) {
    state_ = 0u;
    increment_ = (stream << 1u) | 1u;
    next_u32();
    state_ += seed;
    next_u32();
  }

  constexpr std::uint32_t next_u32() {
    const std::uint64_t old = state_;
    state_ = old * kMultiplier + increment_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  // Uniform float in [0, 1): the top 24 bits scaled by 2^-24, so 1 is never returned.
  constexpr float next_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }

  // Uniform double in [0, 1) from 53 random bits.
  constexpr double next_double() {
    const std::uint64_t hi = next_u32() >> 5, lo = next_u32() >> 6;
    return static_cast<double>((hi << 26) | lo) * 0x1p-53;
  }

  // Uniform integer in [0, bound) without modulo bias (Lemire-free rejection, as in pcg-c).
  constexpr std::uint32_t next_bounded(std::uint32_t bound) {
    const std::uint32_t threshold = (~bound + 1u) % bound;
    for (;;) {
      const std::uint32_t r = next_u32();
      if (r >= threshold) return r % bound;
    }
  }

 private:
  std::uint64_t state_ = kDefaultState;
  std::uint64_t increment_ = kDefaultStream;
};

}  // namespace prism
