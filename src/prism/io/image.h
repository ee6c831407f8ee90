#pragma once
#include <cstdint>
#include <vector>

namespace prism {

// Linear floating-point RGB image, interleaved, row-major from the top-left pixel.
struct ImageRgbF {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 × width × height
};

// Integer-encoded image as stored in PNG: `channels` interleaved samples per pixel,
// each in [0, 2^bit_depth - 1], bit_depth 8 or 16.
struct EncodedImage {
  int width = 0, height = 0;
  int channels = 3;
  int bit_depth = 8;
  std::vector<std::uint16_t> samples;
};

}  // namespace prism
