#include "prism/io/hdr10_metadata.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Rounds to the nearest integer unit, clamped to the field's range.
std::uint32_t to_units(double value, double unit, double max_units) {
  if (!(value > 0.0)) return 0;
  return static_cast<std::uint32_t>(std::min(std::round(value / unit), max_units));
}

void put_u16(std::uint8_t* p, std::uint32_t v) {
  p[0] = static_cast<std::uint8_t>(v >> 8);
  p[1] = static_cast<std::uint8_t>(v);
}
void put_u32(std::uint8_t* p, std::uint32_t v) {
  p[0] = static_cast<std::uint8_t>(v >> 24);
  p[1] = static_cast<std::uint8_t>(v >> 16);
  p[2] = static_cast<std::uint8_t>(v >> 8);
  p[3] = static_cast<std::uint8_t>(v);
}

}  // namespace

ContentLightLevel content_light_level(const std::vector<float>& rgb) {
  ContentLightLevel r;
  const std::size_t n = rgb.size() / 3;
  if (n == 0) return r;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double m = std::max({static_cast<double>(rgb[3 * i]), static_cast<double>(rgb[3 * i + 1]),
                         static_cast<double>(rgb[3 * i + 2]), 0.0});
    if (!std::isfinite(m)) m = 0.0;
    r.max_cll_nits = std::max(r.max_cll_nits, m);
    sum += m;
  }
  r.max_fall_nits = sum / static_cast<double>(n);
  return r;
}

std::array<std::uint8_t, 4> cicp_chunk_data(const CicpInfo& c) {
  return {c.color_primaries, c.transfer_characteristics, c.matrix_coefficients, c.video_full_range};
}

std::array<std::uint8_t, 24> mdcv_chunk_data(const MasteringDisplay& m) {
  std::array<std::uint8_t, 24> d{};
  const double xy[8] = {m.red_x, m.red_y, m.green_x, m.green_y, m.blue_x, m.blue_y, m.white_x, m.white_y};
  for (int i = 0; i < 8; ++i) put_u16(d.data() + 2 * i, to_units(xy[i], 0.00002, 65535.0));
  put_u32(d.data() + 16, to_units(m.max_luminance_nits, 0.0001, 4294967295.0));
  put_u32(d.data() + 20, to_units(m.min_luminance_nits, 0.0001, 4294967295.0));
  return d;
}

std::array<std::uint8_t, 8> clli_chunk_data(const ContentLightLevel& c) {
  std::array<std::uint8_t, 8> d{};
  put_u32(d.data(), to_units(c.max_cll_nits, 0.0001, 4294967295.0));
  put_u32(d.data() + 4, to_units(c.max_fall_nits, 0.0001, 4294967295.0));
  return d;
}

}  // namespace prism
