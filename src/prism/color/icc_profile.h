#pragma once
// ICC display profiles (ICC.1:2022, profile version 4.4) of the matrix/TRC kind: three
// colorants and three tone curves, the form every colour-managed reader understands. They
// tag SDR outputs whose primaries or curve are not plain sRGB (Display P3, Adobe RGB,
// user primaries, BT.1886), where PNG's sRGB chunk would be wrong and cICP alone is not
// yet widely read (Adobe RGB has no cICP code point at all).
#include <cstdint>
#include <string>
#include <vector>

#include "prism/color/color_space.h"

namespace prism::color {

// The curve from encoded value to linear light, as an ICC parametricCurveType.
enum class IccToneCurve {
  srgb,         // IEC 61966-2-1 piecewise curve (function type 3)
  gamma_2_4,    // pure power 2.4: BT.1886 with zero black (function type 0)
  gamma_2_2,    // pure power 563/256 ≈ 2.1992: Adobe RGB (1998) §4.3.4.2 (function type 0)
  gamma_2_6,    // pure power 2.6: the DCI/P3 cinema display EOTF (SMPTE RP 431-2) (function type 0)
};

// The PCS illuminant of ICC.1 (§7.2.16): D50 as XYZ (0.9642, 1, 0.8249).
Vec3d icc_pcs_illuminant_XYZ();

// The colorants of `space` in the PCS: its RGB→XYZ columns adapted from its white to the
// PCS illuminant with the linearised Bradford transform (ICC.1 Annex E), the matrix the
// profile's `chad` tag records.
Mat3 icc_colorant_matrix(const ColorSpace& space);

// A complete v4.4 display-class RGB profile: desc, cprt, wtpt (the PCS illuminant, as v4
// asks of display profiles), chad, rXYZ/gXYZ/bXYZ and shared rTRC/gTRC/bTRC. The profile
// ID is left zero (allowed: "not calculated"); the creation date is fixed so that the same
// output is byte-identical from run to run.
std::vector<std::uint8_t> make_icc_display_profile(const ColorSpace& space, IccToneCurve curve,
                                                   const std::string& description);

}  // namespace prism::color
