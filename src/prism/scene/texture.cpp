#include "prism/scene/texture.h"

#include <algorithm>
#include <cmath>
#include <utility>

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

// stb_image's conversion (stbi__hdr_convert): (float) ldexp(1.0f, e − 136), then the
// mantissa times it; exponent 0 is black.
std::array<float, 256> make_rgbe_exponent_scales() {
  std::array<float, 256> scales{};
  for (int e = 1; e < 256; ++e) scales[static_cast<std::size_t>(e)] = static_cast<float>(std::ldexp(1.0f, e - 136));
  return scales;
}

}  // namespace

namespace detail {
const std::array<float, 256> kSrgbCodeValues = make_code_values(TextureEncoding::srgb);
const std::array<float, 256> kLinearCodeValues = make_code_values(TextureEncoding::linear);
const std::array<float, 256> kRgbeExponentScales = make_rgbe_exponent_scales();
}  // namespace detail

std::vector<float> TextureImage::linear_values() const {
  if (!has_codes() && !has_rgbe() && !has_halves()) return texels;
  std::vector<float> values(sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = value(i);
  return values;
}

void map_texture_values(TextureImage& image, const std::function<float(float)>& f, const std::string& what) {
  std::vector<float> values = image.linear_values();
  const auto channels = static_cast<std::size_t>(image.channels);
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!is_alpha_channel(static_cast<int>(i % channels), image.channels)) values[i] = f(values[i]);
  image.texels = std::move(values);
  image.codes = {};
  image.rgbe = {};
  image.halves = {};
  image.name += " (" + what + ")";
}

void invert_texture_values(TextureImage& image, float scale) {
  map_texture_values(image, [scale](float v) { return std::max(0.0f, 1.0f - scale * v); }, "inverted");
}

}  // namespace prism
