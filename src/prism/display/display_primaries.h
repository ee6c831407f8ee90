#pragma once
// The user's display: RGB primaries and white for the gamut remap after the ODT
// (`--display-primaries`), and the remap itself.
//
// Remap (issue 6 stage 6): the ODT output is display-linear light in the ODT's primaries
// (what its EOTF would decode the code values to), so
//   rgb_user = clip_[0, peak]( M · rgb_odt ),  M = XYZ→RGB_user · Bradford(W_odt → W_user) · RGB_odt→XYZ
// (Lindbloom's RGB↔XYZ; Bradford per color::conversion_matrix), then re-encoded with the
// same encoding. The clip is a hard per-channel clip: colours the display cannot show land
// on its gamut boundary.
#include <string_view>

#include "prism/color/color_space.h"
#include "prism/core/mat3.h"

namespace prism::display {

// A colour-space name ("adobe-rgb", "display-p3", …), "xy:rx,ry,gx,gy,bx,by,wx,wy", or the
// eight numbers alone. UsageError when malformed, collinear, the white outside the
// triangle, or any primary or the white outside the CIE 1931 spectral locus.
color::ColorSpace parse_display_primaries(std::string_view spec);

// M above: display-linear RGB in `odt_space` → RGB in `display`, Bradford-adapted.
Mat3 gamut_remap_matrix(const color::ColorSpace& odt_space, const color::ColorSpace& display);

}  // namespace prism::display
