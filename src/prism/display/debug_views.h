#pragma once
// Debug views of the display pipeline (`--view`), each a function on plain images:
//   luminance / luminance-display   false colour, luminance_view.h
//   gamut-clip                      pixels whose displayed colour lies outside Rec.709, in cyan
//   sdr-hdr-split                   left half SDR at a chosen SDR white, right half HDR
//   chromaticity                    CIE 1931 xy diagram, chromaticity_diagram.h
//   normal                          shading normals as colour (needs an N.x/N.y/N.z AOV)
//   bloom                           the bloom component alone (the halo bloom spreads)
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/display/display_pipeline.h"

namespace prism::display {

enum class DebugView { none, normal, luminance, luminance_display, gamut_clip, sdr_hdr_split, chromaticity, bloom };

// "normal", "luminance", …; UsageError listing the names otherwise.
DebugView parse_debug_view(std::string_view name);
std::vector<std::string> debug_view_names();

// Luminance (nits) of each pixel of RGB data in `space`.
std::vector<float> luminance_nits(const std::vector<float>& rgb, const color::ColorSpace& space);

// Replaces, in place, the pixels whose displayed light converted to Rec.709 (Bradford from
// the output primaries) has a component below −1e-4 of its luminance by cyan — Rec.709
// (0, 1, 1) at min(white, 100) nits — and re-encodes them. Returns how many it marked.
std::size_t mark_gamut_clip(DisplayImage& image);

// The HDR output of `settings` (an HDR ODT, PQ) with its left half replaced by the SDR
// rendering (srgb-100nit's ACES SDR video transform) whose white shows at sdr_white_nits,
// converted to the HDR output's primaries; a one-pixel grey divider marks the seam.
DisplayImage sdr_hdr_split_view(const ImageRgbF& film, const color::ColorSpace& film_space,
                                const DisplaySettings& settings, double sdr_white_nits);

// The bloom component alone: strength · halo of the exposed film's light above the threshold
// (bloom.h bloom_component; with bloom off, what strength 1 would spread), shown through the
// same rendering, target and encoding as the image, with the image's exposure.
DisplayImage bloom_only_view(const ImageRgbF& film, const color::ColorSpace& film_space, const DisplaySettings& settings);

// Surface normals in [−1, 1] as sRGB codes 0.5 + 0.5·N (the usual normal-map colours).
ImageRgbF normal_view(const ImageRgbF& normals);

}  // namespace prism::display
