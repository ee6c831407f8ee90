#pragma once
// IEEE 754 binary16 ("half", OpenEXR's HALF channels) to binary32. Every half is exactly a
// float, so this loses nothing: a half-float texture can keep its 2-byte samples and
// decode them at each lookup into the very floats OpenEXR's half → float conversion gives
// (half_float_test checks all 65 536 against Imath's `half`).
#include <bit>
#include <cstdint>

namespace prism {

constexpr float half_bits_to_float(std::uint16_t bits) {
  const std::uint32_t sign = static_cast<std::uint32_t>(bits & 0x8000u) << 16;
  const std::uint32_t exponent = (bits >> 10) & 0x1fu, mantissa = bits & 0x3ffu;
  float magnitude;
  if (exponent == 0) {
    // Zero and subnormals, m · 2^-24: exact, and computed from an integer so that a
    // denormals-are-zero mode cannot flush them.
    magnitude = static_cast<float>(mantissa) * 0x1p-24f;
  } else if (exponent == 31) {
    magnitude = std::bit_cast<float>(0x7f800000u | mantissa << 13);  // infinity, or NaN with its payload
  } else {
    magnitude = std::bit_cast<float>((exponent + 112u) << 23 | mantissa << 13);  // rebias 15 → 127
  }
  return std::bit_cast<float>(std::bit_cast<std::uint32_t>(magnitude) | sign);
}

}  // namespace prism
