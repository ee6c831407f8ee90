// `prism tonemap IN.(exr|hdr) -o OUT.(png|avif|exr)`: the display pipeline on any
// scene-linear OpenEXR or Radiance picture (see docs/display-pipeline.md). A thin adapter: the options are display_options.h's, every
// stage lives in prism::display.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "command.h"
#include "display_options.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/rendering.h"
#include "prism/display/rendering_pipeline.h"
#include "prism/io/atomic_file.h"
#include "prism/io/png.h"
#include "prism/io/exr.h"
#include "prism/io/read_to_end.h"
#include "prism/io/radiance_hdr_reader.h"
#include "prism/scene/texture_file.h"

namespace prism::cli {
namespace {

struct TonemapOptions {
  std::string input, output;
  bool inverse = false;
  DisplayCliOptions display;
};

// The input's space from its `chromaticities` (Rec.709/D65 when absent, per the EXR spec).
color::ColorSpace film_space(const ExrFile& in) {
  if (!in.has_chromaticities) return color::color_space("srgb");
  const ExrChromaticities& c = in.chromaticities;
  return color::make_color_space("exr-chromaticities", {c.red_x, c.red_y}, {c.green_x, c.green_y},
                                 {c.blue_x, c.blue_y}, {c.white_x, c.white_y});
}

// --inverse: a display image of `--rendering aces2 --odt T` (a PNG's code values, or the
// scRGB light of tonemap's own .exr) back to ACES2065-1 scene light, written as an EXR
// tagged with the AP0 chromaticities.
int run_inverse(const TonemapOptions& o) {
  const display::DisplaySettings s = make_display_settings(o.display);
  if (s.rendering != display::Rendering::aces2) throw UsageError("--inverse needs --rendering aces2");
  const std::filesystem::path out(o.output), in(o.input);
  if (out.extension() != ".exr") throw UsageError("--inverse writes ACES2065-1 scene light: the output must be an .exr");
  check_writable_output(out);
  ImageRgbF code;
  display::DisplayEncoding encoding = s.encoding.value_or(display::default_encoding(s.rendering, s.odt));
  try {
    if (in.extension() == ".png") {
      const PngFile png = read_png(in);
      if (png.image.channels < 3) throw UsageError("--inverse needs an RGB PNG");
      const double max_code = (1 << png.image.bit_depth) - 1;
      code = ImageRgbF{png.image.width, png.image.height, {}};
      const std::size_t n = static_cast<std::size_t>(png.image.width) * png.image.height;
      for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
          code.rgb.push_back(static_cast<float>(png.image.samples[i * png.image.channels + c] / max_code));
    } else {
      code = read_exr(in).image;  // tonemap's display-referred .exr: scRGB light
      encoding = display::DisplayEncoding::scrgb;
    }
  } catch (const IoError& e) {
    throw UsageError(e.what());
  }
  const ImageRgbF aces = display::aces2_inverse(code, encoding, s);
  const color::ColorSpace& ap0 = color::color_space("aces2065-1");
  const auto f = [](double v) { return static_cast<float>(v); };
  ExrMetadata meta;
  meta.strings["prism:inverseOf"] = "aces2 " + std::string(display::odt_description(s.odt).name);
  write_exr(out, aces,
            {f(ap0.red.x), f(ap0.red.y), f(ap0.green.x), f(ap0.green.y), f(ap0.blue.x), f(ap0.blue.y), f(ap0.white.x),
             f(ap0.white.y)},
            meta);
  fmt::print("prism: {}: ACES2065-1 from the aces2 {} display image\n", out.string(), display::odt_description(s.odt).name);
  return 0;
}

int run_tonemap(const TonemapOptions& o) {
  if (o.inverse) return run_inverse(o);
  // Everything the user typed is checked before the input is read or the output touched.
  validate_display_output(o.output, o.display);
  ImageRgbF image;
  color::ColorSpace space;
  std::optional<ImageRgbF> normals;
  DisplayCliOptions display = o.display;
  try {
    // Only a Radiance picture is read whole here; OpenEXR reads its own file.
    if (detect_image_file_format(o.input) == ImageFileFormat::radiance_hdr) {
      // Radiance: the space its header names (PRIMARIES, XYZE; Rec.709 without), its
      // EXPOSURE and COLORCORR divided out (io/radiance_hdr_reader.h).
      RadianceImage hdr = read_radiance_image(read_file_bytes(o.input, "image"), o.input);
      image = ImageRgbF{hdr.width, hdr.height, std::move(hdr.rgb)};
      space = std::move(hdr.space);
    } else {
      ExrFile in = read_exr(o.input);
      normals = read_exr_vector_layer(o.input, "N");
      // A render's coverage (--aov depth) keeps --auto-exposure from metering the void.
      if (display.auto_exposure)
        if (auto coverage = read_exr_channels(o.input, {"Z.coverage"})) display.metering_coverage = std::move(*coverage);
      space = film_space(in);
      image = std::move(in.image);
    }
  } catch (const IoError& e) {
    throw UsageError(e.what());  // unreadable input is the user's input: exit 2
  }
  write_display_output(o.output, image, space, display, normals);
  return 0;
}

// The --help footer: every rendering with the display targets it has.
std::string rendering_target_table() {
  std::string text = "Renderings (--rendering) and their display targets (--odt):\n";
  for (const std::string& name : display::rendering_names()) {
    text += "  " + name + ":";
    for (const std::string& target : display::rendering_target_names(display::parse_rendering(name)))
      text += " " + target;
    text += "\n";
  }
  return text + "A file's values enter unscaled unless --ev100, the camera settings or --auto-exposure is given.";
}

}  // namespace

void add_tonemap_command(CLI::App& root, Action& action) {
  auto opts = std::make_shared<TonemapOptions>();
  CLI::App* cmd = root.add_subcommand("tonemap", "Apply the display pipeline (exposure, rendering, display target, encoding) to an EXR or .hdr");
  cmd->add_option("input", opts->input, "Scene-linear OpenEXR (its chromaticities, Rec.709 when absent, give its space) or Radiance .hdr (its "
                  "PRIMARIES or XYZE format, Rec.709 without)")
      ->required();
  cmd->add_option("-o,--output", opts->output,
                  "Output .png (SDR, or HDR with cICP/mDCv/cLLi), .avif (10/12-bit with CICP) or .exr (scRGB)")
      ->required();
  cmd->add_flag("--inverse", opts->inverse,
                "With --rendering aces2: turn a display image (PNG code values, or this command's scRGB .exr) back "
                "into ACES2065-1 scene light (.exr output)");
  add_display_options(cmd, opts->display);
  cmd->footer(rendering_target_table());
  cmd->callback([&action, opts] { action = [opts] { return run_tonemap(*opts); }; });
}

}  // namespace prism::cli
