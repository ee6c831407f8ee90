#pragma once
// The chromaticity debug view (`--view chromaticity`): a CIE 1931 xy diagram, written as an
// sRGB PNG, with
//   - the spectral locus from the CMF table (spectral_locus.h) and the line of purples, white
//   - grid lines and tick bars every 0.1 with their values (Prism's bitmap font)
//   - gamut triangles: the film's working space (orange), ACES AP0 (magenta), ACES AP1
//     (violet) and the display's primaries (green), with a legend
//   - every image pixel with Y > 0 plotted at its xy, brightness ∝ log(1 + count)
// The plot covers x ∈ [0, 0.8], y ∈ [0, 0.9] with y up.
#include "prism/color/color_space.h"
#include "prism/display/raster.h"

namespace prism::display {

Canvas chromaticity_diagram(const ImageRgbF& film, const color::ColorSpace& film_space,
                            const color::ColorSpace& display_space, int plot_size_px = 480);

// Pixel position of chromaticity (x, y) in a diagram of plot size `plot_size_px`.
Vec3d chromaticity_to_canvas(double x, double y, int plot_size_px);

}  // namespace prism::display
