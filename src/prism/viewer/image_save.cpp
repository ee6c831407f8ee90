// Save actions of the viewer (image_save.h), on the io/ writers.
#include "prism/viewer/image_save.h"

#include <cctype>

#include "prism/core/error.h"
#include "prism/core/version.h"
#include "prism/io/avif.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "prism/io/png_color_tags.h"
#include "prism/io/png_hdr.h"

namespace prism::viewer {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::uint8_t cicp_transfer(display::DisplayEncoding e) {
  switch (e) {
    case display::DisplayEncoding::pq: return 16;
    case display::DisplayEncoding::bt1886: return 1;
    case display::DisplayEncoding::gamma22: return 4;  // H.273: "assumed display gamma 2.2"
    case display::DisplayEncoding::gamma26: return 2;  // no code point: unspecified (the ICC profile says)
    default: return 13;
  }
}

EncodedImage rgba_to_rgb8(const DisplayFrame& shown) {
  EncodedImage out{shown.width, shown.height, 3, 8, {}};
  out.samples.resize(static_cast<std::size_t>(shown.width) * shown.height * 3);
  for (std::size_t i = 0; i < out.samples.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) out.samples[3 * i + c] = shown.rgba[4 * i + c];
  return out;
}

PngColorMetadata png_metadata(const display::DisplayImage& image, const DisplayFrame& shown, const DisplayControls& c) {
  // SDR: sRGB chunk, or an ICC profile (+ cICP) for other primaries and curves; PQ: cICP.
  const color::ColorSpace output = color::parse_color_space(image.primaries);
  const std::uint8_t primaries = cicp_color_primaries(output);
  const bool pq = image.encoding == display::DisplayEncoding::pq;
  PngColorMetadata meta = pq ? PngColorMetadata{} : sdr_png_color_metadata(output, display::icc_tone_curve(image.encoding));
  if (pq && primaries != 0) meta.cicp = CicpInfo{primaries, cicp_transfer(image.encoding), 0, 1};
  if (pq) {
    const color::ColorSpace& p = color::color_space(image.primaries);
    const display::OdtDescription& odt = display::odt_description(c.settings.odt);
    meta.mastering_display = MasteringDisplay{
        p.red.x, p.red.y, p.green.x, p.green.y, p.blue.x, p.blue.y, p.white.x, p.white.y,
        c.mastering_max_nits > 0 ? c.mastering_max_nits : image.white_nits,
        c.mastering_min_nits > 0 ? c.mastering_min_nits : (odt.hdr ? odt.y_min_nits : 0.0001)};
    ContentLightLevel cll = shown.content_light;
    if (c.max_cll_nits > 0) cll.max_cll_nits = c.max_cll_nits;
    if (c.max_fall_nits > 0) cll.max_fall_nits = c.max_fall_nits;
    meta.content_light_level = cll;
  }
  return meta;
}

}  // namespace

void save_display_image(const std::filesystem::path& path, const DisplayFrame& shown, const DisplayControls& c) {
  const std::string ext = lower_extension(path);
  if (ext != ".png" && ext != ".avif") throw UsageError("display images are saved as .png or .avif");
  const bool pipeline_image = shown.image && (c.view == display::DebugView::none);
  if (!pipeline_image) {
    // Debug views (and HDR frames with the UI composited in) are saved as shown.
    if (ext != ".png") throw UsageError("debug views are saved as .png");
    write_png(path, rgba_to_rgb8(shown), PngWriteOptions{false});
    return;
  }
  const display::DisplayImage& image = *shown.image;
  if (display::is_float_encoding(image.encoding)) throw UsageError("scRGB is floating point: save the film EXR instead");
  const std::uint64_t seed = c.settings.dither_seed;
  if (ext == ".avif") {
    const std::uint8_t p = cicp_color_primaries(color::parse_color_space(image.primaries));
    write_avif(path, display::quantise_display_image(image, 10, seed),
               CicpInfo{p ? p : std::uint8_t{2}, cicp_transfer(image.encoding), 0, 1});
    return;
  }
  write_png_with_color_metadata(path, display::quantise_display_image(image, 16, seed), png_metadata(image, shown, c));
}

void save_film_exr(const std::filesystem::path& path, const FilmFrame& film, const std::string& scene_name) {
  if (lower_extension(path) != ".exr") throw UsageError("the film is saved as .exr");
  const color::ColorSpace& s = film.film_space;
  const auto f = [](double v) { return static_cast<float>(v); };
  const ExrChromaticities chroma{f(s.red.x), f(s.red.y), f(s.green.x), f(s.green.y),
                                 f(s.blue.x), f(s.blue.y), f(s.white.x), f(s.white.y)};
  ExrMetadata meta;
  meta.strings["prism:version"] = kVersion;
  meta.strings["prism:scene"] = scene_name;
  meta.strings["prism:source"] = "prism view";
  meta.ints["prism:spp"] = film.spp;
  meta.doubles["prism:renderSeconds"] = film.elapsed_seconds;
  write_exr(path, film.film, chroma, meta);
}

void save_screenshot(const std::filesystem::path& path, const EncodedImage& rgb8) {
  write_png(path, rgb8, PngWriteOptions{true});
}

}  // namespace prism::viewer
