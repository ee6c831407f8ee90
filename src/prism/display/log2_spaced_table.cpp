#include "prism/display/log2_spaced_table.h"

#include <cmath>
#include <stdexcept>

namespace prism::display {

Log2SpacedTable::Log2SpacedTable(const std::function<double(double)>& f, int lo_log2, int hi_log2,
                                 int samples_per_octave_log2) {
  // Normal floats only, and at most 2^23 segments per octave (the mantissa's width).
  if (lo_log2 < -126 || hi_log2 > 127 || lo_log2 >= hi_log2 || samples_per_octave_log2 < 0 ||
      samples_per_octave_log2 > 23)
    throw std::invalid_argument("Log2SpacedTable: bad range");
  lo_ = std::ldexp(1.0f, lo_log2);
  hi_ = std::ldexp(1.0f, hi_log2);
  lo_bits_ = std::bit_cast<std::uint32_t>(lo_);
  shift_ = 23 - samples_per_octave_log2;
  mask_ = (std::uint32_t{1} << shift_) - 1;
  inv_segment_ = std::ldexp(1.0f, -shift_);
  const std::size_t segments = static_cast<std::size_t>(hi_log2 - lo_log2) << samples_per_octave_log2;
  std::vector<double> value(segments + 1);
  for (std::size_t i = 0; i <= segments; ++i)
    value[i] = f(static_cast<double>(std::bit_cast<float>(lo_bits_ + static_cast<std::uint32_t>(i << shift_))));
  // One extra entry with zero rise: x = hi lands on it with a zero fraction.
  segments_.resize(segments + 1);
  for (std::size_t i = 0; i <= segments; ++i)
    segments_[i] = {static_cast<float>(value[i]), i < segments ? static_cast<float>(value[i + 1] - value[i]) : 0.0f};
  const double f0 = f(0.0);
  f0_ = static_cast<float>(f0);
  below_slope_ = static_cast<float>((value[0] - f0) / lo_);
}

void Log2SpacedTable::anchor_zero(double x_zero) {
  const auto x = static_cast<float>(x_zero);
  if (!(x >= lo_ && x < hi_)) return;
  const std::uint32_t i = (std::bit_cast<std::uint32_t>(x) - lo_bits_) >> shift_;
  const double start = std::bit_cast<float>(lo_bits_ + (i << shift_));
  const double end = std::bit_cast<float>(lo_bits_ + ((i + 1) << shift_));
  const double end_value = static_cast<double>(segments_[i][0]) + segments_[i][1];
  const double rise = end_value * (end - start) / (end - x_zero);
  segments_[i] = {static_cast<float>(end_value - rise), static_cast<float>(rise)};
}

}  // namespace prism::display
