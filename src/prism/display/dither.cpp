#include "prism/display/dither.h"

#include <cmath>

namespace prism::display {
namespace {

// SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix.
std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

double triangular_dither_lsb(std::uint64_t seed, std::uint64_t index) {
  const std::uint64_t h = mix64(mix64(seed) ^ index);
  // Two 32-bit uniforms in [0, 1); their difference is triangular on (−1, 1).
  const double u1 = static_cast<double>(h >> 32) * 0x1p-32;
  const double u2 = static_cast<double>(h & 0xffffffffull) * 0x1p-32;
  return u1 - u2;
}

std::uint16_t quantise_code(double code, int bits, double noise_lsb) {
  const double max_code = std::exp2(bits) - 1.0;
  if (std::isnan(code)) return 0;
  const double v = std::round(code * max_code + noise_lsb);
  if (v <= 0.0) return 0;
  if (v >= max_code) return static_cast<std::uint16_t>(max_code);
  return static_cast<std::uint16_t>(v);
}

}  // namespace prism::display
