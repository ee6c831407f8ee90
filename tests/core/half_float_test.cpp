#include "prism/core/half_float.h"

#include <gtest/gtest.h>

#include <Imath/half.h>

#include <bit>
#include <cstdint>

namespace prism {
namespace {

// Every one of the 65 536 halves against Imath's conversion (what OpenEXR uses to read a
// HALF channel into a FLOAT slice), bit for bit: zeros of both signs, subnormals,
// normals, infinities and NaNs with their payloads.
TEST(HalfFloat, EveryHalfConvertsAsImathConvertsIt) {
  for (std::uint32_t bits = 0; bits <= 0xffffu; ++bits) {
    imath_half_bits_t h = static_cast<imath_half_bits_t>(bits);
    const float expected = imath_half_to_float(h);
    ASSERT_EQ(std::bit_cast<std::uint32_t>(half_bits_to_float(static_cast<std::uint16_t>(bits))),
              std::bit_cast<std::uint32_t>(expected))
        << std::hex << bits;
  }
}

TEST(HalfFloat, KnownValues) {
  EXPECT_EQ(half_bits_to_float(0x3c00), 1.0f);
  EXPECT_EQ(half_bits_to_float(0xc000), -2.0f);
  EXPECT_EQ(half_bits_to_float(0x7bff), 65504.0f);        // the largest half
  EXPECT_EQ(half_bits_to_float(0x0001), 0x1p-24f);         // the smallest subnormal
  EXPECT_EQ(half_bits_to_float(0x0400), 0x1p-14f);         // the smallest normal
  EXPECT_EQ(std::bit_cast<std::uint32_t>(half_bits_to_float(0x8000)), 0x80000000u);  // −0
}

}  // namespace
}  // namespace prism
