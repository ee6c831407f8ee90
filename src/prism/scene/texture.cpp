#include "prism/scene/texture.h"

#include "prism/color/transfer_functions.h"

namespace prism {
namespace {

std::array<float, 256> make_code_values(TextureEncoding encoding) {
  std::array<float, 256> values{};
  for (std::size_t code = 0; code < values.size(); ++code) {
    const double v = static_cast<double>(code) / 255.0;
    values[code] = static_cast<float>(encoding == TextureEncoding::srgb ? color::srgb_decode(v) : v);
  }
  return values;
}

}  // namespace

namespace detail {
const std::array<float, 256> kSrgbCodeValues = make_code_values(TextureEncoding::srgb);
const std::array<float, 256> kLinearCodeValues = make_code_values(TextureEncoding::linear);
}  // namespace detail

std::vector<float> TextureImage::linear_values() const {
  if (!has_codes()) return texels;
  std::vector<float> values(codes.size());
  for (std::size_t i = 0; i < codes.size(); ++i) values[i] = value(i);
  return values;
}

}  // namespace prism
