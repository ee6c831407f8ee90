#pragma once
// The display pipeline on a whole image: exposure → bloom → to ACES2065-1 (one 3×3 with
// Bradford adaptation) → blue-light LMT → ACES RRT + ODT up to its normalised AP1 step →
// render-scale upscale → overlay/UI → display light → gamut remap to the user's display →
// encoding → optional quantisation with dither. Settings are a plain struct that the CLI, scene files and the
// viewer fill the same way. See docs/display-pipeline.md.
//
// The per-pixel work runs in AcesOutputKernel (float, tabulated curves, blocks of pixels,
// rows in parallel with prism::parallel_for); DisplaySettings::reference_path runs the
// exact double-precision AcesOutputTransform per pixel instead (tests bound the difference).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/display/aces_output_transform.h"
#include "prism/display/bloom.h"
#include "prism/display/ui_overlay.h"
#include "prism/display/display_encoding.h"
#include "prism/display/rendering.h"
#include "prism/io/image.h"

namespace prism::display {

struct DisplaySettings {
  // Exposure: at most one of these; none leaves the stored values unscaled.
  std::optional<double> exposure_ev100;
  bool auto_exposure = false;
  double auto_exposure_key = 0.18;
  // Auto exposure meters only what the camera saw: per pixel, the fraction of its samples
  // that hit a surface (a render's Z.coverage layer), as exposure_metering.h weighs it.
  // Empty: every finite pixel counts. Otherwise one value per film pixel.
  std::vector<float> metering_coverage;
  double blue_correction = 0.0;                 // LMT strength in [0, 1]
  // The rendering transform and the display target it renders for (rendering.h); other
  // renderings than aces1 run in rendering_pipeline.h.
  Rendering rendering = Rendering::aces1;
  OdtId odt = OdtId::srgb_100nit;
  std::optional<DisplayEncoding> encoding;      // default: default_encoding(rendering, odt)
  // aces2 only: the display's peak luminance, 100–10000 nits (default: the target's preset).
  std::optional<double> peak_nits;
  std::optional<bool> stretch_black;            // default: the Academy's (on)
  std::uint64_t dither_seed = 0x70726973;       // "pris"
  BloomSettings bloom;                          // strength 0: off
  // The user's display (--display-primaries): remap the ODT's output to it. None: the ODT's.
  std::optional<color::ColorSpace> display_primaries;
  // The film was rendered at this fraction of the output size (--render-scale); the
  // displayed image is upscaled bilinearly to round(size / render_scale).
  double render_scale = 1.0;
  std::optional<UiOverlay> overlay;             // composited at the output size
  // true: the exact double-precision ACES path (AcesOutputTransform per pixel), the
  // reference the tests hold the float/tabulated block kernel (aces_output_kernel.h) to.
  bool reference_path = false;
};

// What the display shows, before quantisation.
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<float> code;   // encoded values, 3 per pixel (scrgb: linear, may be < 0 or > 1)
  std::vector<float> nits;   // display-linear light in the output primaries, nits
  DisplayEncoding encoding = DisplayEncoding::srgb;
  std::string primaries;     // prism::color name of the output RGB primaries
  double white_nits = 100;   // light of code 1 for relative encodings; ODT peak otherwise
  double exposure_scale = 1; // factor applied to the input
  double y_max_nits = 100;   // the ODT's peak (before any gamut remap)
};

// The exposure factor the settings ask for on this image (1 when none). Validates.
double exposure_scale(const DisplaySettings& s, const ImageRgbF& film, const color::ColorSpace& film_space);

// The 3×3 from the film's RGB to ACES2065-1 (Bradford to the ACES white) with the blue-light
// LMT of the given strength folded in.
Mat3 film_to_aces_matrix(const color::ColorSpace& film_space, double blue_correction);

DisplayImage apply_display_pipeline(const ImageRgbF& film, const color::ColorSpace& film_space,
                                    const DisplaySettings& settings);

// Integer samples of `bit_depth` bits (8, 10, 12 or 16); TPDF dither of one LSB for 8 and
// 10 bits (seeded), none above. Float encodings: UsageError.
EncodedImage quantise_display_image(const DisplayImage& image, int bit_depth, std::uint64_t dither_seed);

}  // namespace prism::display
