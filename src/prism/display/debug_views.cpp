#include "prism/display/debug_views.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"

namespace prism::display {
namespace {

constexpr std::pair<DebugView, const char*> kViews[] = {
    {DebugView::normal, "normal"},
    {DebugView::luminance, "luminance"},
    {DebugView::luminance_display, "luminance-display"},
    {DebugView::gamut_clip, "gamut-clip"},
    {DebugView::sdr_hdr_split, "sdr-hdr-split"},
    {DebugView::chromaticity, "chromaticity"},
    {DebugView::bloom, "bloom"},
};

void set_pixel(DisplayImage& image, std::size_t i, const Vec3d& nits) {
  for (int c = 0; c < 3; ++c) {
    image.nits[3 * i + c] = static_cast<float>(nits[c]);
    image.code[3 * i + c] = static_cast<float>(encode_display_nits(image.encoding, nits[c], image.white_nits));
  }
}

}  // namespace

DebugView parse_debug_view(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& [v, s] : kViews)
    if (n == s) return v;
  std::string valid;
  for (const auto& [v, s] : kViews) valid += (valid.empty() ? "" : ", ") + std::string(s);
  throw UsageError("unknown view '" + std::string(name) + "' (valid: " + valid + ")");
}

std::vector<std::string> debug_view_names() {
  std::vector<std::string> r;
  for (const auto& [v, s] : kViews) r.emplace_back(s);
  return r;
}

std::vector<float> luminance_nits(const std::vector<float>& rgb, const color::ColorSpace& space) {
  const Vec3d w = space.rgb_to_xyz.row(1);
  std::vector<float> y(rgb.size() / 3);
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] = static_cast<float>(w.x * rgb[3 * i] + w.y * rgb[3 * i + 1] + w.z * rgb[3 * i + 2]);
  return y;
}

std::size_t mark_gamut_clip(DisplayImage& image) {
  const color::ColorSpace out = color::parse_color_space(image.primaries);
  const color::ColorSpace& rec709 = color::color_space("srgb");
  const Mat3 to_709 = color::conversion_matrix(out, rec709, color::Cat::bradford);
  const Mat3 from_709 = color::conversion_matrix(rec709, out, color::Cat::bradford);
  const double cyan_nits = std::min(image.white_nits, 100.0);
  const Vec3d cyan = from_709 * Vec3d{0.0, cyan_nits, cyan_nits};
  const Vec3d lum = out.rgb_to_xyz.row(1);
  std::size_t marked = 0;
  for (std::size_t i = 0; i < image.nits.size() / 3; ++i) {
    const Vec3d rgb{image.nits[3 * i], image.nits[3 * i + 1], image.nits[3 * i + 2]};
    const Vec3d r709 = to_709 * rgb;
    const double y = std::max(dot(lum, rgb), 1e-6);
    if (std::min({r709.x, r709.y, r709.z}) < -1e-4 * y) {
      set_pixel(image, i, cyan);
      ++marked;
    }
  }
  return marked;
}

DisplayImage sdr_hdr_split_view(const ImageRgbF& film, const color::ColorSpace& film_space, const DisplaySettings& s,
                                double sdr_white_nits) {
  if (!odt_description(s.odt).hdr) throw UsageError("the sdr-hdr-split view needs an HDR ODT (e.g. rec2020-pq-1000nit)");
  if (s.encoding && *s.encoding != DisplayEncoding::pq && *s.encoding != DisplayEncoding::scrgb)
    throw UsageError("the sdr-hdr-split view needs an HDR encoding (pq or scrgb)");
  if (!(sdr_white_nits > 0.0 && sdr_white_nits <= 10000.0)) throw UsageError("the SDR white must be in (0, 10000] nits");
  DisplayImage hdr = apply_display_pipeline(film, film_space, s);
  DisplaySettings sdr_settings = s;
  sdr_settings.odt = OdtId::srgb_100nit;
  sdr_settings.encoding = DisplayEncoding::srgb;
  sdr_settings.display_primaries.reset();
  const DisplayImage sdr = apply_display_pipeline(film, film_space, sdr_settings);
  const Mat3 to_out = color::conversion_matrix(color::color_space("srgb"), color::parse_color_space(hdr.primaries),
                                               color::Cat::bradford);
  const double gain = sdr_white_nits / odt_description(OdtId::srgb_100nit).white_nits;
  const int half = hdr.width / 2;
  for (int y = 0; y < hdr.height; ++y)
    for (int x = 0; x <= half && x < hdr.width; ++x) {
      const std::size_t i = std::size_t(y) * hdr.width + x;
      const Vec3d light = x == half ? Vec3d{sdr_white_nits, sdr_white_nits, sdr_white_nits} * 0.5
                                    : to_out * (Vec3d{sdr.nits[3 * i], sdr.nits[3 * i + 1], sdr.nits[3 * i + 2]} * gain);
      set_pixel(hdr, i, light);
    }
  return hdr;
}

DisplayImage bloom_only_view(const ImageRgbF& film, const color::ColorSpace& film_space, const DisplaySettings& s) {
  const double scale = exposure_scale(s, film, film_space);
  ImageRgbF exposed = film;
  for (float& v : exposed.rgb) v = std::isfinite(v) ? static_cast<float>(v * scale) : 0.0f;
  BloomSettings bloom = s.bloom;
  if (!(bloom.strength > 0.0)) bloom.strength = 1.0;
  DisplaySettings shown = s;
  shown.bloom.strength = 0.0;  // the component is already the bloom
  shown.auto_exposure = false;
  shown.exposure_ev100 = -std::log2(1.2);  // scale 1: the component is exposed already
  return apply_display_pipeline(bloom_component(exposed, bloom), film_space, shown);
}

ImageRgbF normal_view(const ImageRgbF& n) {
  ImageRgbF out = n;
  for (float& v : out.rgb) v = std::isfinite(v) ? std::clamp(0.5f + 0.5f * v, 0.0f, 1.0f) : 0.0f;
  return out;
}

}  // namespace prism::display
