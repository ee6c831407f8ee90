#include "prism/display/clamp_srgb_encode.h"

#include <algorithm>
#include <cmath>

#include "prism/color/transfer_functions.h"

namespace prism {

EncodedImage clamp_srgb_encode(const ImageRgbF& linear, int bit_depth) {
  EncodedImage out;
  out.width = linear.width;
  out.height = linear.height;
  out.channels = 3;
  out.bit_depth = bit_depth;
  out.samples.resize(linear.rgb.size());
  const double max_code = bit_depth == 16 ? 65535.0 : 255.0;
  for (std::size_t i = 0; i < linear.rgb.size(); ++i) {
    const float v = linear.rgb[i];
    const double clamped = std::isnan(v) ? 0.0 : std::clamp(static_cast<double>(v), 0.0, 1.0);
    out.samples[i] = static_cast<std::uint16_t>(std::lround(color::srgb_encode(clamped) * max_code));
  }
  return out;
}

}  // namespace prism
