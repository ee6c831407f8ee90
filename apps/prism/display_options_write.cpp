// Writing a display-referred output (PNG, AVIF, scRGB EXR) or a debug view from scene-linear
// film, for `prism tonemap` and `prism render`. Declared in display_options.h.
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "display_options.h"
#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/display/chromaticity_diagram.h"
#include "prism/display/debug_views.h"
#include "prism/display/luminance_view.h"
#include "prism/display/ocio_display.h"
#include "prism/io/atomic_file.h"
#include "prism/io/avif.h"
#include "prism/io/exr_scrgb.h"
#include "prism/io/png.h"
#include "prism/io/png_color_tags.h"
#include "prism/io/png_hdr.h"

namespace prism::cli {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool ocio_mode(const DisplayCliOptions& o) { return uses_ocio(o); }

display::DebugView debug_view(const DisplayCliOptions& o) {
  return o.view.empty() || ocio_mode(o) ? display::DebugView::none : display::parse_debug_view(o.view);
}

std::uint8_t cicp_transfer(display::DisplayEncoding e) {
  switch (e) {
    case display::DisplayEncoding::pq: return 16;
    case display::DisplayEncoding::bt1886: return 1;
    case display::DisplayEncoding::gamma22: return 4;  // H.273: "assumed display gamma 2.2"
    default: return 13;
  }
}

// An EXR output is display-linear scRGB unless --encoding says otherwise (which the
// validation refuses): the light the target shows, not its code values.
display::DisplayEncoding output_encoding(const std::string& ext, const display::DisplaySettings& s) {
  return s.encoding.value_or(ext == ".exr" ? display::DisplayEncoding::scrgb
                                           : display::default_encoding(s.rendering, s.odt));
}

// The settings for `output`: the encoding made explicit (scRGB for .exr).
display::DisplaySettings output_settings(const std::string& ext, const DisplayCliOptions& o) {
  display::DisplaySettings s = make_display_settings(o);
  s.encoding = output_encoding(ext, s);
  return s;
}

// What the file says about how it was made: the rendering and the display target.
std::vector<PngText> display_png_text(const display::DisplaySettings& s) {
  std::vector<PngText> text{{"prism:rendering", std::string(display::rendering_name(s.rendering))},
                            {"prism:displayTarget", std::string(display::odt_description(s.odt).name)}};
  // The exposure used, exactly (shortest round-trip form): `--ev100` repeats the picture.
  if (s.exposure_ev100) text.push_back({"prism:ev100", fmt::format("{}", *s.exposure_ev100)});
  return text;
}

void write_png_view(const std::filesystem::path& out, const display::Canvas& canvas) {
  write_png(out, display::canvas_to_srgb8(canvas), PngWriteOptions{true});
}

void write_shown(const std::filesystem::path& out, const std::string& ext, const display::DisplayImage& shown,
                 const display::DisplaySettings& s, const DisplayCliOptions& o) {
  if (ext == ".exr") {
    ExrMetadata meta;
    meta.strings["prism:rendering"] = std::string(display::rendering_name(s.rendering));
    meta.strings["prism:displayTarget"] = std::string(display::odt_description(s.odt).name);
    write_exr_scrgb(out, ImageRgbF{shown.width, shown.height, shown.code}, 80.0, meta);
    return;
  }
  const color::ColorSpace primaries = color::parse_color_space(shown.primaries);
  const std::uint8_t cp = cicp_color_primaries(primaries);
  if (ext == ".avif") {
    // AVIF needs a CICP triple; primaries without a code point are "unspecified" (2).
    write_avif(out, display::quantise_display_image(shown, o.bit_depth ? o.bit_depth : 10, s.dither_seed),
               CicpInfo{cp ? cp : std::uint8_t{2}, cicp_transfer(shown.encoding), 0, 1});
    return;
  }
  // SDR: sRGB chunk, or an ICC profile (+ cICP) for other primaries and curves; PQ: cICP.
  const bool pq = shown.encoding == display::DisplayEncoding::pq;
  PngColorMetadata meta = pq ? PngColorMetadata{} : sdr_png_color_metadata(primaries, display::icc_tone_curve(shown.encoding));
  meta.text = display_png_text(s);
  for (const auto& [keyword, text] : o.extra_png_text) meta.text.push_back({keyword, text});
  if (pq && cp != 0) meta.cicp = CicpInfo{cp, cicp_transfer(shown.encoding), 0, 1};
  if (pq) {
    const display::OdtDescription& odt = display::odt_description(s.odt);
    const color::ColorSpace& p = primaries;
    meta.mastering_display = MasteringDisplay{p.red.x, p.red.y, p.green.x, p.green.y, p.blue.x, p.blue.y,
                                              p.white.x, p.white.y, o.mastering_max_nits.value_or(shown.white_nits),
                                              o.mastering_min_nits.value_or(odt.hdr ? odt.y_min_nits : 0.0001)};
    ContentLightLevel cll = content_light_level(shown.nits);
    if (o.max_cll) cll.max_cll_nits = *o.max_cll;
    if (o.max_fall) cll.max_fall_nits = *o.max_fall;
    meta.content_light_level = cll;
  }
  write_png_with_color_metadata(out, display::quantise_display_image(shown, o.bit_depth ? o.bit_depth : 16, s.dither_seed),
                                meta);
}

// The OpenColorIO path: the config's code values, which OCIO does not describe — PNG without
// colour chunks, AVIF with unspecified CICP primaries and transfer (2, 2) — and the config,
// display and view in the PNG's text.
void write_ocio_output(const std::filesystem::path& out, const std::string& ext, const ImageRgbF& film,
                       double exposure_scale, const display::DisplaySettings& s, const DisplayCliOptions& o) {
  const display::OcioDisplaySettings ocio = ocio_settings(o);
  const display::OcioDisplayView chosen = display::resolve_ocio_display_view(ocio);
  const display::DisplayImage shown = display::apply_ocio_display(film, exposure_scale, ocio);
  if (ext == ".avif") {
    write_avif(out, display::quantise_display_image(shown, o.bit_depth ? o.bit_depth : 10, s.dither_seed),
               CicpInfo{2, 2, 0, 1});
    return;
  }
  PngColorMetadata meta;
  meta.text = {{"prism:rendering", "ocio"},
               {"prism:ocioConfig", ocio.config_path},
               {"prism:ocioDisplay", chosen.display},
               {"prism:ocioView", chosen.view}};
  write_png_with_color_metadata(out, display::quantise_display_image(shown, o.bit_depth ? o.bit_depth : 16, s.dither_seed),
                                meta);
}

}  // namespace

void validate_display_output(const std::filesystem::path& out, const DisplayCliOptions& o) {
  const std::string ext = lower_extension(out);
  if (ext != ".png" && ext != ".exr" && ext != ".avif")
    throw UsageError("output '" + out.string() + "' must end in .png, .avif or .exr");
  const display::DisplaySettings s = make_display_settings(o);
  const display::DebugView view = debug_view(o);
  const display::DisplayEncoding enc = output_encoding(ext, s);
  if (s.display_primaries && enc == display::DisplayEncoding::scrgb)
    throw UsageError("scRGB is defined on Rec.709 primaries: --display-primaries needs a .png/.avif output");
  if (ocio_mode(o) && ext == ".exr")
    throw UsageError("the OpenColorIO path writes display code values to .png or .avif; for an .exr name --rendering or --odt");
  if (ocio_mode(o)) display::resolve_ocio_display_view(ocio_settings(o));  // bad config/display/view
  if (view != display::DebugView::none && view != display::DebugView::gamut_clip &&
      view != display::DebugView::sdr_hdr_split && view != display::DebugView::bloom && ext != ".png")
    throw UsageError("--view " + o.view + " writes a PNG");
  if (ext == ".exr" && enc != display::DisplayEncoding::scrgb)
    throw UsageError("EXR output holds linear scRGB: use --encoding scrgb or a .png/.avif output");
  if (ext != ".exr" && enc == display::DisplayEncoding::scrgb)
    throw UsageError("scRGB is floating point: write it to an .exr output");
  if (ext == ".png" && o.bit_depth != 0 && o.bit_depth != 8 && o.bit_depth != 16)
    throw UsageError("--bit-depth must be 8 or 16 for PNG");
  if (ext == ".avif" && o.bit_depth != 0 && o.bit_depth != 10 && o.bit_depth != 12)
    throw UsageError("--bit-depth must be 10 or 12 for AVIF");
  if (view == display::DebugView::sdr_hdr_split && !display::odt_description(s.odt).hdr)
    throw UsageError("the sdr-hdr-split view needs an HDR ODT (e.g. rec2020-pq-1000nit)");
  check_writable_output(out);
}

display::DebugView selected_debug_view(const DisplayCliOptions& options) { return debug_view(options); }

void write_display_output(const std::filesystem::path& out, const ImageRgbF& film, const color::ColorSpace& film_space,
                          const DisplayCliOptions& o, const std::optional<ImageRgbF>& normals) {
  validate_display_output(out, o);
  const std::string ext = lower_extension(out);
  const display::DisplaySettings s = output_settings(ext, o);
  // Which rendering (or OpenColorIO config) made the file: one line per display output.
  fmt::print("prism: {}: {}\n", out.string(), describe_display(o));
  if (ocio_mode(o)) {
    write_ocio_output(out, ext, film, display::exposure_scale(s, film, film_space), s, o);
    return;
  }
  switch (debug_view(o)) {
    case display::DebugView::normal: {
      if (!normals) throw UsageError("--view normal needs a shading-normal AOV (N.x, N.y, N.z channels) in the input");
      display::Canvas canvas(normals->width, normals->height, {0, 0, 0});
      canvas.image = display::normal_view(*normals);
      write_png(out, display::canvas_to_srgb8(canvas), PngWriteOptions{false});
      return;
    }
    case display::DebugView::luminance: {
      const std::vector<float> y = display::luminance_nits(film.rgb, film_space);
      write_png_view(out, display::luminance_false_colour_view(y, film.width, film.height, display::luminance_scale_for(y)));
      return;
    }
    case display::DebugView::luminance_display: {
      const display::DisplayImage shown = display::apply_display_pipeline(film, film_space, s);
      const std::vector<float> y = display::luminance_nits(shown.nits, color::parse_color_space(shown.primaries));
      write_png_view(out, display::luminance_false_colour_view(y, shown.width, shown.height, display::luminance_scale_for(y)));
      return;
    }
    case display::DebugView::chromaticity: {
      const display::OdtDescription& odt = display::odt_description(s.odt);
      const color::ColorSpace shown_space = s.display_primaries ? *s.display_primaries : color::color_space(odt.display_space);
      write_png_view(out, display::chromaticity_diagram(film, film_space, shown_space));
      return;
    }
    case display::DebugView::gamut_clip: {
      display::DisplayImage shown = display::apply_display_pipeline(film, film_space, s);
      display::mark_gamut_clip(shown);
      write_shown(out, ext, shown, s, o);
      return;
    }
    case display::DebugView::bloom:
      write_shown(out, ext, display::bloom_only_view(film, film_space, s), s, o);
      return;
    case display::DebugView::sdr_hdr_split:
      write_shown(out, ext, display::sdr_hdr_split_view(film, film_space, s, o.sdr_white_nits), s, o);
      return;
    case display::DebugView::none:
      write_shown(out, ext, display::apply_display_pipeline(film, film_space, s), s, o);
      return;
  }
}

}  // namespace prism::cli
