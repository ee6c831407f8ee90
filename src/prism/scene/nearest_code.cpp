#include "prism/scene/nearest_code.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace prism {

std::array<float, 255> code_midpoints(const std::array<float, 256>& values) {
  std::array<float, 255> midpoints{};
  for (std::size_t k = 0; k < midpoints.size(); ++k) midpoints[k] = 0.5f * (values[k] + values[k + 1]);
  return midpoints;
}

std::uint8_t nearest_code_by_midpoints(const std::array<float, 256>& values, const std::array<float, 255>& midpoints,
                                       float v) {
  if (!(v > 0.0f)) return 0;  // and NaN
  if (v >= 1.0f) return 255;
  std::size_t k = static_cast<std::size_t>(std::upper_bound(midpoints.begin(), midpoints.end(), v) - midpoints.begin());
  const auto error = [&](std::size_t code) { return std::abs(values[code] - v); };
  if (k > 0 && error(k - 1) < error(k)) --k;
  if (k < 255 && error(k + 1) < error(k)) ++k;
  return static_cast<std::uint8_t>(k);
}

NearestCode::NearestCode(const std::array<float, 256>& values) {
  const std::array<float, 255> midpoints = code_midpoints(values);
  for (std::size_t k = 0; k + 1 < thresholds_.size(); ++k) {
    // The least float in (values[k], values[k + 1]] answered with more than k: values are
    // non-negative, so their bit patterns order as they do.
    std::uint32_t lo = std::bit_cast<std::uint32_t>(values[k]), hi = std::bit_cast<std::uint32_t>(values[k + 1]);
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (nearest_code_by_midpoints(values, midpoints, std::bit_cast<float>(mid)) > k) hi = mid;
      else lo = mid;
    }
    thresholds_[k] = std::bit_cast<float>(hi);
  }
  thresholds_.back() = std::numeric_limits<float>::infinity();
  const auto count_at_or_below = [&](float v) {
    return static_cast<std::size_t>(std::upper_bound(thresholds_.begin(), thresholds_.end() - 1, v) - thresholds_.begin());
  };
  for (int b = 0; b < kBuckets; ++b) {
    const std::size_t first = count_at_or_below(static_cast<float>(b) / kBuckets);
    // operator() steps once at most: more than one threshold in a bucket's (b, b + 1] / kBuckets
    // would need a walk (not for code tables of 256 values in [0, 1] as sRGB and linear are).
    const std::size_t last = count_at_or_below(static_cast<float>(b + 1) / kBuckets);
    if (last - first > 1)
      throw std::logic_error("NearestCode: " + std::to_string(last - first) + " thresholds in bucket " +
                             std::to_string(b) + " (at most 1 is supported)");
    first_[static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(first);
  }
}

}  // namespace prism
