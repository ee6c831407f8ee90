#pragma once
// The CIE 1931 spectral locus in xy, from the tabulated colour-matching functions
// (prism::color::cie1931_xyz_bar), closed by the line of purples: the boundary of all
// physically realisable chromaticities. Used to validate display primaries and to draw
// the chromaticity diagram.
#include <vector>

#include "prism/color/chromaticity.h"

namespace prism::display {

// xy of monochromatic light from 380 to 700 nm in 1 nm steps. Above 700 nm the CMFs'
// chromaticity barely moves and folds back on itself in the table's rounding, so the
// locus (and the purple line) ends at 700 nm.
const std::vector<color::Chromaticity>& spectral_locus_xy();

// Whether c lies inside the closed locus, or within `tolerance` (xy distance) outside it.
// Rec.2020's primaries are monochromatic and P3's red lies on the long-wavelength edge
// (x + y = 1); published to 3 decimals (±5e-4) they can sit just outside the tabulated
// locus, so the default allows 2e-3 — a tenth of the smallest step that makes a real
// difference between display gamuts.
bool inside_spectral_locus(color::Chromaticity c, double tolerance = 2e-3);

}  // namespace prism::display
