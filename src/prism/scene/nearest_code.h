#pragma once
// The 8-bit code whose value is nearest to a linear value: how a mip level of an 8-bit
// texture rounds the box filter's average back to codes (texture_sampling.cpp).
#include <array>
#include <cstdint>

namespace prism {

// The definition: with `values` ascending from 0 to 1 (a code → value table) and
// `midpoints` its code_midpoints, the number of midpoints at or below v, settled against
// its neighbours (a midpoint rounded to float can put a v within an ulp of it on the wrong
// side). 0 for v ≤ 0 and NaN, 255 for v ≥ 1.
std::array<float, 255> code_midpoints(const std::array<float, 256>& values);  // ½(values[k] + values[k + 1])
std::uint8_t nearest_code_by_midpoints(const std::array<float, 256>& values, const std::array<float, 255>& midpoints,
                                       float v);

// The same codes, fast: nearest_code_by_midpoints is non-decreasing in v (between two
// neighbouring values it answers the lower code, then the upper one), so it is the number
// of thresholds at or below v, where threshold k is the least float it answers more than k
// for (found once, by bisection over the floats between values[k] and values[k + 1]). A
// table of that number at multiples of 1/kBuckets starts the count; a bucket holds one
// threshold at most even where the codes are densest (sRGB near 0: 1/(255 · 12.92) =
// 3.0e-4 apart, five buckets; the constructor checks it for every bucket), so the count is
// the table's plus at most one step, taken without a branch (its outcome is a coin flip
// from texel to texel).
class NearestCode {
 public:
  explicit NearestCode(const std::array<float, 256>& values);
  std::uint8_t operator()(float v) const {
    if (!(v > 0.0f)) return 0;  // and NaN
    if (v >= 1.0f) return 255;
    const std::size_t k = first_[static_cast<std::size_t>(v * kBuckets)];
    return static_cast<std::uint8_t>(k + static_cast<std::size_t>(thresholds_[k] <= v));
  }
  float threshold(int k) const { return thresholds_[static_cast<std::size_t>(k)]; }

 private:
  static constexpr int kBuckets = 1 << 14;
  // Thresholds 0–254, then +∞ (no code above 255), so the step reads no further check.
  std::array<float, 256> thresholds_{};
  std::array<std::uint8_t, kBuckets> first_{};  // thresholds at or below bucket / kBuckets
};

}  // namespace prism
