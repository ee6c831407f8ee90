#pragma once
// Bitwise float equality, for tests that demand identical results (it tells -0 from +0 and
// accepts equal NaN payloads, which == does not). Declared once so that the test files
// can share a translation unit (unity builds).
#include <bit>
#include <cstdint>

namespace prism::test {

inline bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

}  // namespace prism::test
