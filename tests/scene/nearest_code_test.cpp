#include "prism/scene/nearest_code.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "prism/scene/texture.h"

namespace prism {
namespace {

// Floats to check for one code table: a sweep of every 257th float in [0, 1] (4 million),
// and the floats within 8 ulps of every value, midpoint and threshold (where an off-by-one
// or a rounding side would show), and the ends.
std::vector<float> probes(const std::array<float, 256>& values, const NearestCode& fast) {
  std::vector<float> v = {0.0f, -0.0f, -1.0f, 1.0f, 2.0f, std::nextafter(1.0f, 0.0f),
                          std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::denorm_min()};
  for (std::uint32_t bits = 0; bits <= std::bit_cast<std::uint32_t>(1.0f); bits += 257)
    v.push_back(std::bit_cast<float>(bits));
  std::vector<float> centres(values.begin(), values.end());
  for (const float m : code_midpoints(values)) centres.push_back(m);
  for (int k = 0; k < 255; ++k) centres.push_back(fast.threshold(k));
  for (const float c : centres)
    for (int d = -8; d <= 8; ++d)
      v.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(std::int64_t{std::bit_cast<std::uint32_t>(c)} + d)));
  return v;
}

// The threshold table answers exactly what the midpoint definition answers (so mip levels
// are bitwise those of the definition), and the definition answers a nearest code: no
// neighbouring code's value is strictly nearer (ties may go either way).
TEST(NearestCode, ThresholdsAnswerTheMidpointDefinition) {
  for (const TextureEncoding encoding : {TextureEncoding::srgb, TextureEncoding::linear}) {
    const std::array<float, 256>& values = code_values(encoding);
    const std::array<float, 255> midpoints = code_midpoints(values);
    const NearestCode fast(values);
    for (const float v : probes(values, fast)) {
      const std::uint8_t code = nearest_code_by_midpoints(values, midpoints, v);
      ASSERT_EQ(fast(v), code) << static_cast<int>(encoding) << " v " << v << " bits "
                               << std::bit_cast<std::uint32_t>(v);
      if (!(v > 0.0f) || v >= 1.0f) continue;
      const float error = std::abs(values[code] - v);
      if (code > 0) {
        ASSERT_LE(error, std::abs(values[code - 1u] - v)) << v;
      }
      if (code < 255) {
        ASSERT_LE(error, std::abs(values[code + 1u] - v)) << v;
      }
    }
  }
}

// What the thresholds rest on: the definition never steps back as v grows.
TEST(NearestCode, TheDefinitionIsNonDecreasing) {
  for (const TextureEncoding encoding : {TextureEncoding::srgb, TextureEncoding::linear}) {
    const std::array<float, 256>& values = code_values(encoding);
    const std::array<float, 255> midpoints = code_midpoints(values);
    std::uint8_t last = 0;
    for (std::uint32_t bits = 0; bits <= std::bit_cast<std::uint32_t>(1.0f); bits += 61) {
      const std::uint8_t code = nearest_code_by_midpoints(values, midpoints, std::bit_cast<float>(bits));
      ASSERT_GE(code, last) << bits;
      last = code;
    }
  }
}

}  // namespace
}  // namespace prism
