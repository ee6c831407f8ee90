#pragma once
// Luminance false colour (`--view luminance|luminance-display`): each pixel's luminance in
// nits on a log10 scale, one colour band per decade, with a legend strip below the image
// carrying tick bars at every decade and their values in nits (Prism's bitmap font).
//
//   scene:   Y = the film's luminance as stored (row 2 of its RGB→XYZ), before exposure
//            and tone mapping — physical nits when the film holds physical units
//   display: Y = luminance of the displayed light (ODT output, nits)
// The scale spans whole decades from the 1st percentile (floor) to the maximum (ceil),
// at least 2 and at most 8 decades; below the range: black, above: white.
#include <vector>

#include "prism/core/vec.h"
#include "prism/display/raster.h"

namespace prism::display {

struct LuminanceScale {
  int min_decade, max_decade;  // log10 of the ends, in nits
};

LuminanceScale luminance_scale_for(const std::vector<float>& luminance_nits);

// The colour of log10(Y) on the scale (sRGB code values): dark blue → blue → green →
// yellow → red → white across the range.
Vec3d false_colour(double luminance_nits, const LuminanceScale& scale);

// The false-colour image with its legend strip below (height grows by the strip).
Canvas luminance_false_colour_view(const std::vector<float>& luminance_nits, int width, int height,
                                   const LuminanceScale& scale);

// "0.01", "1", "100", "1E4": the legend's label for 10^decade nits.
std::string decade_label(int decade);

}  // namespace prism::display
