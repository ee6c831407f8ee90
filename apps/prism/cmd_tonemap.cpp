// `prism tonemap IN.exr -o OUT.(png|exr)`: the display pipeline on any scene-linear EXR
// (see docs/display-pipeline.md). A thin adapter: every stage lives in prism::display.
#include <cctype>
#include <cmath>
#include <memory>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "command.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/exposure.h"
#include "prism/io/atomic_file.h"
#include "prism/io/exr.h"
#include "prism/io/exr_scrgb.h"
#include "prism/io/png_hdr.h"

namespace prism::cli {
namespace {

struct TonemapOptions {
  std::string input, output;
  std::string odt = "srgb-100nit", encoding;
  std::optional<double> ev100, f_number, shutter_s, iso;
  bool auto_exposure = false;
  double key = 0.18, blue_correction = 0.0;
  bool stretch_black = false, no_stretch_black = false;
  int bit_depth = 16;  // the input is float, so 16-bit PNG unless asked otherwise
  std::optional<double> mastering_max_nits, mastering_min_nits, max_cll, max_fall;
  std::uint64_t dither_seed = 0x70726973;
};

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The input's space from its `chromaticities` (Rec.709/D65 when absent, per the EXR spec).
color::ColorSpace film_space(const ExrFile& in) {
  if (!in.has_chromaticities) return color::color_space("srgb");
  const ExrChromaticities& c = in.chromaticities;
  return color::make_color_space("exr-chromaticities", {c.red_x, c.red_y}, {c.green_x, c.green_y},
                                 {c.blue_x, c.blue_y}, {c.white_x, c.white_y});
}

// H.273 code points for cICP.
std::uint8_t cicp_primaries(const std::string& space) {
  if (space == "rec2020") return 9;
  if (space == "display-p3") return 12;
  return 1;
}
std::uint8_t cicp_transfer(display::DisplayEncoding e) {
  switch (e) {
    case display::DisplayEncoding::pq: return 16;
    case display::DisplayEncoding::bt1886: return 1;
    default: return 13;
  }
}

void require_positive_optional(const std::optional<double>& v, const char* what) {
  if (v && !(*v >= 0.0 && std::isfinite(*v))) throw UsageError(std::string(what) + " must be a non-negative number");
}

display::DisplaySettings make_settings(const TonemapOptions& o) {
  display::DisplaySettings s;
  s.odt = display::parse_odt(o.odt);
  if (!o.encoding.empty()) s.encoding = display::parse_display_encoding(o.encoding);
  const bool camera = o.f_number || o.shutter_s || o.iso;
  if (int(o.ev100.has_value()) + int(camera) + int(o.auto_exposure) > 1)
    throw UsageError("give one of --ev100, --f-number/--shutter/--iso or --auto-exposure");
  if (o.ev100) {
    if (!std::isfinite(*o.ev100)) throw UsageError("--ev100 must be a finite number");
    s.exposure_ev100 = *o.ev100;
  } else if (camera) {
    if (!o.f_number || !o.shutter_s || !o.iso) throw UsageError("--f-number, --shutter and --iso go together");
    s.exposure_ev100 = display::ev100_from_camera(*o.f_number, *o.shutter_s, *o.iso);
  }
  s.auto_exposure = o.auto_exposure;
  s.auto_exposure_key = o.key;
  if (!(o.key > 0.0 && std::isfinite(o.key))) throw UsageError("--key must be a positive number");
  if (!(o.blue_correction >= 0.0 && o.blue_correction <= 1.0))
    throw UsageError("--blue-correction must be in [0, 1]");
  s.blue_correction = o.blue_correction;
  if (o.stretch_black && o.no_stretch_black)
    throw UsageError("--odt-stretch-black and --no-odt-stretch-black contradict each other");
  if (o.stretch_black) s.stretch_black = true;
  if (o.no_stretch_black) s.stretch_black = false;
  s.dither_seed = o.dither_seed;
  return s;
}

int run_tonemap(const TonemapOptions& o) {
  // Everything the user typed is checked before the input is read or the output touched.
  const std::string ext = lower_extension(o.output);
  if (ext != ".png" && ext != ".exr") throw UsageError("output '" + o.output + "' must end in .png or .exr");
  display::DisplaySettings s = make_settings(o);
  if (ext == ".exr" && !s.encoding) s.encoding = display::DisplayEncoding::scrgb;
  const display::DisplayEncoding encoding = s.encoding.value_or(display::odt_description(s.odt).default_encoding);
  if (ext == ".exr" && encoding != display::DisplayEncoding::scrgb)
    throw UsageError("EXR output holds linear scRGB: use --encoding scrgb or a .png output");
  if (ext == ".png" && encoding == display::DisplayEncoding::scrgb)
    throw UsageError("scRGB is floating point: write it to an .exr output");
  if (o.bit_depth != 8 && o.bit_depth != 16) throw UsageError("--bit-depth must be 8 or 16");
  require_positive_optional(o.mastering_max_nits, "--mastering-max-nits");
  require_positive_optional(o.mastering_min_nits, "--mastering-min-nits");
  require_positive_optional(o.max_cll, "--max-cll");
  require_positive_optional(o.max_fall, "--max-fall");
  check_writable_output(o.output);

  ExrFile in;
  try {
    in = read_exr(o.input);
  } catch (const IoError& e) {
    throw UsageError(e.what());  // unreadable input is the user's input: exit 2
  }
  const display::DisplayImage shown = display::apply_display_pipeline(in.image, film_space(in), s);

  if (ext == ".exr") {
    write_exr_scrgb(o.output, ImageRgbF{shown.width, shown.height, shown.code});
    return 0;
  }
  PngColorMetadata meta;
  if (shown.primaries == "srgb" && encoding == display::DisplayEncoding::srgb) {
    meta.srgb_chunk = true;
  } else {
    meta.cicp = CicpInfo{cicp_primaries(shown.primaries), cicp_transfer(encoding), 0, 1};
  }
  if (encoding == display::DisplayEncoding::pq) {
    const color::ColorSpace& p = color::color_space(shown.primaries);
    const display::OdtDescription& odt = display::odt_description(s.odt);
    meta.mastering_display = MasteringDisplay{p.red.x, p.red.y, p.green.x, p.green.y, p.blue.x, p.blue.y,
                                              p.white.x, p.white.y, o.mastering_max_nits.value_or(shown.white_nits),
                                              o.mastering_min_nits.value_or(odt.hdr ? odt.y_min_nits : 0.0001)};
    ContentLightLevel cll = content_light_level(shown.nits);
    if (o.max_cll) cll.max_cll_nits = *o.max_cll;
    if (o.max_fall) cll.max_fall_nits = *o.max_fall;
    meta.content_light_level = cll;
  }
  write_png_with_color_metadata(o.output, display::quantise_display_image(shown, o.bit_depth, s.dither_seed), meta);
  return 0;
}

}  // namespace

void add_tonemap_command(CLI::App& root, Action& action) {
  auto opts = std::make_shared<TonemapOptions>();
  CLI::App* cmd = root.add_subcommand("tonemap", "Apply the display pipeline (exposure, ACES RRT+ODT, encoding) to an EXR");
  cmd->add_option("input", opts->input, "Scene-linear OpenEXR; its chromaticities (Rec.709 when absent) give its space")
      ->required();
  cmd->add_option("-o,--output", opts->output, "Output .png (SDR, or HDR with cICP/mDCv/cLLi) or .exr (scRGB)")
      ->required();
  cmd->add_option("--odt", opts->odt, "Output transform: " + [] {
    std::string n;
    for (const auto& s : display::odt_names()) n += (n.empty() ? "" : ", ") + s;
    return n;
  }() + " (default srgb-100nit)");
  cmd->add_option("--encoding", opts->encoding, "srgb, bt1886, pq or scrgb (default: the ODT's; scrgb for .exr)");
  cmd->add_option("--ev100", opts->ev100, "Exposure value at ISO 100; max luminance 1.2·2^EV100 maps to 1.0");
  cmd->add_option("--f-number", opts->f_number, "Camera aperture (with --shutter and --iso)");
  cmd->add_option("--shutter", opts->shutter_s, "Camera shutter time in seconds");
  cmd->add_option("--iso", opts->iso, "Camera ISO sensitivity");
  cmd->add_flag("--auto-exposure", opts->auto_exposure, "Expose the log-average luminance to --key");
  cmd->add_option("--key", opts->key, "Auto-exposure key value (default 0.18)");
  cmd->add_option("--blue-correction", opts->blue_correction, "Blue-light-artifact LMT strength 0..1 (default 0)");
  cmd->add_flag("--odt-stretch-black", opts->stretch_black,
                "HDR: map the ODT's black to 0 nit instead of Y_MIN (the default, as in the Academy's CTL)");
  cmd->add_flag("--no-odt-stretch-black", opts->no_stretch_black, "HDR: keep the ODT's black at Y_MIN (0.0001 nit)");
  cmd->add_option("--bit-depth", opts->bit_depth, "PNG bit depth, 8 or 16 (default 16; 8 is dithered)");
  cmd->add_option("--mastering-max-nits", opts->mastering_max_nits, "mDCv maximum luminance (default: ODT peak)");
  cmd->add_option("--mastering-min-nits", opts->mastering_min_nits, "mDCv minimum luminance (default 0.0001)");
  cmd->add_option("--max-cll", opts->max_cll, "cLLi MaxCLL in nits (default: computed from the image)");
  cmd->add_option("--max-fall", opts->max_fall, "cLLi MaxFALL in nits (default: computed from the image)");
  cmd->add_option("--dither-seed", opts->dither_seed, "Seed of the 8-bit dither");
  cmd->callback([&action, opts] { action = [opts] { return run_tonemap(*opts); }; });
}

}  // namespace prism::cli
