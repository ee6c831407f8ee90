#include "prism/scene/texture_primaries.h"

#include <cmath>

#include <fmt/format.h>
#include <half.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/half_float.h"
#include "prism/scene/emission.h"

namespace prism {

bool same_primaries(const color::Primaries& given, const color::ColorSpace& space) {
  const color::Chromaticity pairs[4][2] = {
      {given.red, space.red}, {given.green, space.green}, {given.blue, space.blue}, {given.white, space.white}};
  for (const auto& [a, b] : pairs)
    if (std::abs(a.x - b.x) > 1e-4 || std::abs(a.y - b.y) > 1e-4) return false;
  return true;
}

std::string primaries_text(const color::Primaries& p) {
  return fmt::format("red {:.4f},{:.4f} green {:.4f},{:.4f} blue {:.4f},{:.4f} white {:.4f},{:.4f}", p.red.x,
                     p.red.y, p.green.x, p.green.y, p.blue.x, p.blue.y, p.white.x, p.white.y);
}

ColorPickerSpace texel_space_for(TextureContent content, const color::ColorSpace& file_space) {
  return content == TextureContent::color_own_gamut ? smallest_picker_space_holding(file_space)
                                                     : requested_space(content);
}

std::size_t convert_texels(TextureImage& image, const Mat3& conversion, ColorPickerSpace target) {
  const std::size_t texels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  std::size_t clipped = 0;
  const auto convert = [&](Vec3d rgb) {
    const Vec3d v = conversion * rgb;
    if (color::is_outside_gamut(v)) ++clipped;
    return max(v, Vec3d(0.0));
  };
  const auto stride = static_cast<std::size_t>(image.channels);  // RGB or RGBA: alpha stays
  for (std::size_t t = 0; t < texels; ++t) {
    if (image.has_halves()) {
      std::uint16_t* h = image.halves.data() + stride * t;
      const Vec3d v = convert(Vec3d(half_bits_to_float(h[0]), half_bits_to_float(h[1]), half_bits_to_float(h[2])));
      for (int k = 0; k < 3; ++k) h[k] = Imath::half(static_cast<float>(v[k])).bits();
    } else {
      float* f = image.texels.data() + stride * t;
      const Vec3d v = convert(Vec3d(f[0], f[1], f[2]));
      for (int k = 0; k < 3; ++k) f[k] = static_cast<float>(v[k]);
    }
  }
  image.texel_space = target;
  return clipped;
}

std::string clipped_texels_text(std::size_t clipped, const TextureImage& image) {
  if (clipped == 0) return "";
  return fmt::format("; {} of {} texels lie outside {} and were clipped to it", clipped,
                     static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height),
                     picker_space_label(image.texel_space));
}

}  // namespace prism
