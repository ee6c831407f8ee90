#pragma once
// The display options shared by `prism tonemap` and `prism render` (issue 6): one struct the
// command line fills, turned into display::DisplaySettings, and one call that writes a
// display-referred output file (PNG, AVIF or scRGB EXR, or a debug view) from scene-linear
// film. See docs/display-pipeline.md.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/display/debug_views.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/ocio_display.h"
#include "prism/io/image.h"

namespace prism::cli {

struct DisplayCliOptions {
  // PNG tEXt chunks the caller adds about how the image was made (keyword, text), after the
  // display's own (e.g. `prism render`'s adaptive-sampling settings). Not a command-line option.
  std::vector<std::pair<std::string, std::string>> extra_png_text;
  std::string rendering;  // empty: the default rendering (display::kDefaultRendering)
  std::string odt;        // empty: srgb-100nit
  std::string encoding;
  std::optional<double> peak_nits;  // --peak-nits, aces2 only
  std::optional<double> ev100, f_number, shutter_s, iso;
  bool auto_exposure = false;
  double key = 0.18, blue_correction = 0.0;
  // What --auto-exposure meters (display::DisplaySettings::metering_coverage): `tonemap`
  // fills it from the input's Z.coverage layer. Not a command-line option.
  std::vector<float> metering_coverage;
  bool stretch_black = false, no_stretch_black = false;
  int bit_depth = 0;  // 0: 16 for PNG (the input is float), 10 for AVIF
  std::optional<double> mastering_max_nits, mastering_min_nits, max_cll, max_fall;
  std::uint64_t dither_seed = 0x70726973;
  double bloom = 0.0, bloom_threshold = 1.0;
  std::string bloom_threshold_space = "hsv";
  std::string display_primaries;
  double render_scale = 1.0;
  std::string view;           // debug view, or the OCIO view with --ocio-config/--display
  double sdr_white_nits = 200.0;
  std::string overlay;
  double ui_nits = 200.0, ui_blend_power = 5.0;
  std::string ocio_config, ocio_display, ocio_input_space;
  // $OCIO as the command line found it (add_display_options reads it; empty when unset): with
  // neither --rendering nor --odt, the outputs go through that config's default display and
  // view, as OpenColorIO's own tools and Blender do.
  std::string ocio_environment;
};

// Whether the options select the OpenColorIO path: --ocio-config or --display, or $OCIO with
// neither --rendering nor --odt.
bool uses_ocio(const DisplayCliOptions& options);
// The OpenColorIO settings of that path (the config: --ocio-config, else $OCIO).
display::OcioDisplaySettings ocio_settings(const DisplayCliOptions& options);
// One line for the summary: "OpenColorIO config C, display D, view V" or "rendering R,
// target T". Throws UsageError for a bad OCIO config/display/view.
std::string describe_display(const DisplayCliOptions& options);

// Adds --rendering, --odt, --encoding, exposure, --bloom…, --display-primaries, --render-scale, --view,
// --overlay/--ui-nits, --ocio-config/--display, HDR10 metadata, --bit-depth, --dither-seed.
void add_display_options(CLI::App* cmd, DisplayCliOptions& options);

// The debug view --view selects (none without --view, or with --ocio-config/--display).
// Throws UsageError for unknown names.
display::DebugView selected_debug_view(const DisplayCliOptions& options);

// Validates and converts (reads the overlay PNG). Throws UsageError.
display::DisplaySettings make_display_settings(const DisplayCliOptions& options);

// Everything about `output` and the options that can be checked before any work: extension,
// option combinations, writability. Throws UsageError / IoError.
void validate_display_output(const std::filesystem::path& output, const DisplayCliOptions& options);

// Runs the display pipeline (or the OCIO path, or a debug view) on scene-linear `film` in
// `film_space` and writes `output` (.png, .avif or .exr by extension). `normals`: the N
// AOV for --view normal. `output_size`: the displayed size when the film was rendered at
// --render-scale of it (default: round(film size / render scale)).
void write_display_output(const std::filesystem::path& output, const ImageRgbF& film,
                          const color::ColorSpace& film_space, const DisplayCliOptions& options,
                          const std::optional<ImageRgbF>& normals = std::nullopt);

}  // namespace prism::cli
