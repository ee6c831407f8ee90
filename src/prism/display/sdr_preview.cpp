#include "prism/display/sdr_preview.h"

#include <algorithm>
#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"

namespace prism::display {
namespace {

void set_light(DisplayImage& image, std::size_t i, const Vec3d& nits) {
  for (int c = 0; c < 3; ++c) {
    image.nits[3 * i + c] = static_cast<float>(nits[c]);
    image.code[3 * i + c] = static_cast<float>(encode_display_nits(image.encoding, nits[c], image.white_nits));
  }
}

}  // namespace

DisplayImage sdr_preview_of_display_light(const DisplayImage& hdr, double sdr_white_nits) {
  if (!(sdr_white_nits > 0.0 && std::isfinite(sdr_white_nits))) throw UsageError("the SDR white must be positive");
  const color::ColorSpace& rec709 = color::color_space("srgb");
  const Mat3 to_709 = color::conversion_matrix(color::parse_color_space(hdr.primaries), rec709, color::Cat::bradford);
  const Vec3d lum = rec709.rgb_to_xyz.row(1);
  const double lw = std::max(hdr.white_nits / sdr_white_nits, 1.0);
  DisplayImage out;
  out.width = hdr.width;
  out.height = hdr.height;
  out.encoding = DisplayEncoding::srgb;
  out.primaries = "srgb";
  out.white_nits = 100.0;
  out.y_max_nits = 100.0;
  out.exposure_scale = hdr.exposure_scale;
  out.code.resize(hdr.nits.size());
  out.nits.resize(hdr.nits.size());
  for (std::size_t i = 0; i < hdr.nits.size() / 3; ++i) {
    const Vec3d rel = to_709 * Vec3d{hdr.nits[3 * i], hdr.nits[3 * i + 1], hdr.nits[3 * i + 2]} / sdr_white_nits;
    const double y = dot(lum, rel);
    const double scale = y > 0.0 ? (1.0 + y / (lw * lw)) / (1.0 + y) : 0.0;
    Vec3d rgb = rel * scale;
    for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c], 0.0, 1.0) * out.white_nits;
    set_light(out, i, rgb);
  }
  return out;
}

DisplayImage transfer_marks(const DisplayImage& unmarked, const DisplayImage& marked, const DisplayImage& preview) {
  if (unmarked.code.size() != marked.code.size() || marked.code.size() != preview.code.size())
    throw Error("transfer_marks: images of different sizes");
  DisplayImage out = preview;
  const Mat3 from_709 = color::conversion_matrix(color::color_space("srgb"), color::parse_color_space(out.primaries),
                                                 color::Cat::bradford);
  const double cyan_nits = std::min(out.white_nits, 100.0);
  const Vec3d cyan = from_709 * Vec3d{0.0, cyan_nits, cyan_nits};
  for (std::size_t i = 0; i < marked.code.size() / 3; ++i)
    if (marked.code[3 * i] != unmarked.code[3 * i] || marked.code[3 * i + 1] != unmarked.code[3 * i + 1] ||
        marked.code[3 * i + 2] != unmarked.code[3 * i + 2])
      set_light(out, i, cyan);
  return out;
}

}  // namespace prism::display
