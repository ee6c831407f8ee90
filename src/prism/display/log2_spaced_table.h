#pragma once
// A 1-D function tabulated at log2-spaced abscissae without computing a logarithm: the
// samples sit at the floats whose bit patterns are evenly spaced, 2^k of them per octave
// (x = 2^e · (1 + j/2^k)), so a positive float's own exponent and top k mantissa bits are
// its segment index and the remaining mantissa bits its position inside the segment, in
// which the table interpolates linearly in x (the idea behind half-float-domain LUTs, at a
// chosen resolution). Used for the ACES tone curves and the display encodings, which are
// smooth in log–log; the interpolation error per segment is ≤ max|f''|·h²/8 with h ≤ x/2^k.
//
// Domain: inputs are clamped to [0, hi]; between 0 and the first sample `lo` the table
// interpolates linearly between f(0) and f(lo); NaN reads as 0.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

namespace prism::display {

class Log2SpacedTable {
 public:
  Log2SpacedTable() = default;
  // f sampled on [2^lo_log2, 2^hi_log2] with 2^samples_per_octave_log2 segments per octave
  // (f evaluated in double, stored as float), plus f(0).
  Log2SpacedTable(const std::function<double(double)>& f, int lo_log2, int hi_log2, int samples_per_octave_log2);

  float operator()(float x) const {
    const float c = x > 0.0f ? std::min(x, hi_) : 0.0f;  // NaN reads as 0, never as an index
    if (c < lo_) return f0_ + below_slope_ * c;
    const std::uint32_t u = std::bit_cast<std::uint32_t>(c) - lo_bits_;
    const std::array<float, 2>& s = segments_[u >> shift_];
    return s[0] + static_cast<float>(u & mask_) * inv_segment_ * s[1];
  }

  std::size_t size() const { return segments_.size(); }

  // For a function that is 0 up to x_zero and then rises linearly from it (the square root
  // of a tone curve leaving its black floor with zero slope): the segment holding x_zero is
  // replaced by the line through (x_zero, 0) and the segment's end, which is negative below
  // x_zero (callers clamp). Without it the chord across the corner errs by ~slope·h/4.
  void anchor_zero(double x_zero);

 private:
  std::vector<std::array<float, 2>> segments_;  // value at the segment start, rise to the next
  float lo_ = 0, hi_ = 0, f0_ = 0, below_slope_ = 0, inv_segment_ = 0;
  std::uint32_t lo_bits_ = 0, mask_ = 0;
  int shift_ = 0;
};

}  // namespace prism::display
