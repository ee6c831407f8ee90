// The display options of `prism tonemap` and `prism render`: the CLI11 definitions and the
// conversion to display::DisplaySettings. Writing is in display_options_write.cpp.
#include "display_options.h"

#include <cmath>
#include <cstdlib>

#include "prism/core/error.h"
#include "prism/display/display_primaries.h"
#include "prism/display/exposure.h"
#include "prism/io/png.h"

namespace prism::cli {

void add_display_options(CLI::App* cmd, DisplayCliOptions& o) {
  cmd->add_option("--rendering", o.rendering, "Rendering transform: " + [] {
    std::string n;
    for (const auto& s : display::rendering_names()) n += (n.empty() ? "" : ", ") + s;
    return n;
  }() + " (default " + std::string(display::rendering_name(display::kDefaultRendering)) + "); with --odt as the display target");
  cmd->add_option("--odt", o.odt, "Output transform: " + [] {
    std::string n;
    for (const auto& s : display::odt_names()) n += (n.empty() ? "" : ", ") + s;
    return n;
  }() + " (default srgb-100nit; with $OCIO set and neither --odt nor --rendering: the config's default display and view)");
  cmd->add_option("--peak-nits", o.peak_nits,
                  "aces2: the display's peak luminance, 100..10000 nits (default: the target's preset)");
  cmd->add_option("--encoding", o.encoding, "srgb, bt1886, pq or scrgb (default: the ODT's; scrgb for .exr)");
  cmd->add_option("--ev100", o.ev100, "Exposure value at ISO 100; max luminance 1.2·2^EV100 maps to 1.0");
  cmd->add_option("--f-number", o.f_number, "Camera aperture (with --shutter and --iso)");
  cmd->add_option("--shutter", o.shutter_s, "Camera shutter time in seconds");
  cmd->add_option("--iso", o.iso, "Camera ISO sensitivity");
  cmd->add_flag("--auto-exposure", o.auto_exposure,
                "Meter the image (the 10th-90th percentile mean of log luminance over zones that see a surface, "
                "docs/display-pipeline.md) and expose it to --key; render does this unless an exposure is given");
  cmd->add_option("--key", o.key, "Auto-exposure key value (default 0.18)");
  cmd->add_option("--blue-correction", o.blue_correction, "Blue-light-artifact LMT strength 0..1 (default 0)");
  cmd->add_flag("--odt-stretch-black", o.stretch_black,
                "HDR: map the ODT's black to 0 nit instead of Y_MIN (the default, as in the Academy's CTL)");
  cmd->add_flag("--no-odt-stretch-black", o.no_stretch_black, "HDR: keep the ODT's black at Y_MIN (0.0001 nit)");
  cmd->add_option("--bit-depth", o.bit_depth, "PNG: 8 or 16 (default 16; 8 is dithered); AVIF: 10 or 12 (default 10)");
  cmd->add_option("--mastering-max-nits", o.mastering_max_nits, "mDCv maximum luminance (default: ODT peak)");
  cmd->add_option("--mastering-min-nits", o.mastering_min_nits, "mDCv minimum luminance (default 0.0001)");
  cmd->add_option("--max-cll", o.max_cll, "cLLi MaxCLL in nits (default: computed from the image)");
  cmd->add_option("--max-fall", o.max_fall, "cLLi MaxFALL in nits (default: computed from the image)");
  cmd->add_option("--dither-seed", o.dither_seed, "Seed of the 8/10-bit dither");
  cmd->add_option("--bloom", o.bloom, "Bloom strength 0..1: the share of above-max-luminance light spread into a halo (default 0, off)");
  cmd->add_option("--bloom-threshold", o.bloom_threshold, "Bloom threshold in exposed units (default 1 = max luminance)");
  cmd->add_option("--bloom-threshold-space", o.bloom_threshold_space, "hsv (threshold on V, keeps hue; default) or rgb (per channel)");
  cmd->add_option("--display-primaries", o.display_primaries,
                  "Remap to the display's primaries: a name (adobe-rgb, display-p3, …) or xr,yr,xg,yg,xb,yb,xw,yw");
  cmd->add_option("--render-scale", o.render_scale, "The film is this fraction (0, 1] of the output size: upscale bilinearly");
  cmd->add_option("--view", o.view,
                  "Debug view: normal, luminance, luminance-display, gamut-clip, sdr-hdr-split, chromaticity, bloom; "
                  "with --ocio-config/--display: the OCIO view");
  cmd->add_option("--sdr-white", o.sdr_white_nits, "sdr-hdr-split view: SDR white in nits (default 200)");
  cmd->add_option("--overlay", o.overlay, "RGBA sRGB PNG composited in HDR (same size as the output)");
  cmd->add_option("--ui-nits", o.ui_nits, "Overlay white luminance, 80..300 nits (default 200)");
  cmd->add_option("--ui-blend-power", o.ui_blend_power, "Overlay peak blend power p: weight alpha^p (default 5)");
  cmd->add_option("--ocio-config", o.ocio_config,
                  "Use this OpenColorIO config's display and view ($OCIO when only --display, or when neither "
                  "--rendering nor --odt is given)");
  // The command line is where the environment is read; the library takes the path.
  if (const char* env = std::getenv("OCIO")) o.ocio_environment = env;
  cmd->add_option("--display", o.ocio_display, "OCIO display name (OCIO path)");
  cmd->add_option("--ocio-input-space", o.ocio_input_space, "OCIO colour space of the film (default: role scene_linear)");
}

namespace {

void require_non_negative(const std::optional<double>& v, const char* what) {
  if (v && !(*v >= 0.0 && std::isfinite(*v))) throw UsageError(std::string(what) + " must be a non-negative number");
}

}  // namespace

bool uses_ocio(const DisplayCliOptions& o) {
  return !o.ocio_config.empty() || !o.ocio_display.empty() ||
         (!o.ocio_environment.empty() && o.rendering.empty() && o.odt.empty());
}

display::OcioDisplaySettings ocio_settings(const DisplayCliOptions& o) {
  return {o.ocio_config.empty() ? o.ocio_environment : o.ocio_config, o.ocio_display, o.view, o.ocio_input_space};
}

std::string describe_display(const DisplayCliOptions& o) {
  if (uses_ocio(o)) {
    const display::OcioDisplaySettings ocio = ocio_settings(o);
    const display::OcioDisplayView chosen = display::resolve_ocio_display_view(ocio);
    return "OpenColorIO config " + ocio.config_path + (o.ocio_config.empty() ? " ($OCIO)" : "") + ", display '" +
           chosen.display + "', view '" + chosen.view + "'";
  }
  const display::DisplaySettings s = make_display_settings(o);
  return "rendering " + std::string(display::rendering_name(s.rendering)) + ", target " +
         std::string(display::odt_description(s.odt).name);
}

display::DisplaySettings make_display_settings(const DisplayCliOptions& o) {
  display::DisplaySettings s;
  s.rendering = o.rendering.empty() ? display::kDefaultRendering : display::parse_rendering(o.rendering);
  s.odt = display::parse_odt(o.odt.empty() ? "srgb-100nit" : o.odt);
  display::require_rendering_target(s.rendering, s.odt);
  if (o.peak_nits) {
    if (s.rendering != display::Rendering::aces2) throw UsageError("--peak-nits needs --rendering aces2");
    if (!(*o.peak_nits >= 100.0 && *o.peak_nits <= 10000.0)) throw UsageError("--peak-nits must be in [100, 10000]");
    s.peak_nits = *o.peak_nits;
  }
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
  if (!(o.key > 0.0 && std::isfinite(o.key))) throw UsageError("--key must be a positive number");
  s.auto_exposure_key = o.key;
  s.metering_coverage = o.metering_coverage;
  if (!(o.blue_correction >= 0.0 && o.blue_correction <= 1.0)) throw UsageError("--blue-correction must be in [0, 1]");
  s.blue_correction = o.blue_correction;
  if (o.stretch_black && o.no_stretch_black)
    throw UsageError("--odt-stretch-black and --no-odt-stretch-black contradict each other");
  if (o.stretch_black) s.stretch_black = true;
  if (o.no_stretch_black) s.stretch_black = false;
  s.dither_seed = o.dither_seed;
  if (!(o.bloom >= 0.0 && o.bloom <= 1.0)) throw UsageError("--bloom must be in [0, 1]");
  if (!(o.bloom_threshold >= 0.0 && std::isfinite(o.bloom_threshold)))
    throw UsageError("--bloom-threshold must be a non-negative number");
  s.bloom.strength = o.bloom;
  s.bloom.threshold = o.bloom_threshold;
  s.bloom.threshold_space = display::parse_bloom_threshold_space(o.bloom_threshold_space);
  if (!o.display_primaries.empty()) s.display_primaries = display::parse_display_primaries(o.display_primaries);
  if (!(o.render_scale > 0.0 && o.render_scale <= 1.0)) throw UsageError("--render-scale must be in (0, 1]");
  s.render_scale = o.render_scale;
  if (!(o.sdr_white_nits > 0.0 && o.sdr_white_nits <= 10000.0)) throw UsageError("--sdr-white must be in (0, 10000] nits");
  if (!(o.ui_nits >= 80.0 && o.ui_nits <= 300.0)) throw UsageError("--ui-nits must be in [80, 300]");
  if (!(o.ui_blend_power > 0.0 && std::isfinite(o.ui_blend_power))) throw UsageError("--ui-blend-power must be positive");
  require_non_negative(o.mastering_max_nits, "--mastering-max-nits");
  require_non_negative(o.mastering_min_nits, "--mastering-min-nits");
  require_non_negative(o.max_cll, "--max-cll");
  require_non_negative(o.max_fall, "--max-fall");
  if (!o.overlay.empty()) {
    PngFile png;
    try {
      png = read_png(o.overlay);
    } catch (const IoError& e) {
      throw UsageError(e.what());
    }
    s.overlay = display::make_ui_overlay(png.image, o.ui_nits, o.ui_blend_power);
  }
  return s;
}

}  // namespace prism::cli
