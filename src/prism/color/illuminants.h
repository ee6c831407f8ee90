#pragma once
// CIE standard illuminants, tabulated at 1 nm (data/cie/, CC BY-SA 4.0, see
// data/SOURCES.md), as relative spectral power distributions (100 at 560 nm).
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/chromaticity.h"
#include "prism/color/spectrum.h"

namespace prism::color {

enum class StandardIlluminant { d65, d50, a, e };

// The tabulated SPD, 300–830 nm at 1 nm.
const DenseSpectrum& standard_illuminant(StandardIlluminant illuminant);
// "d65", "d50", "a", "e" (case-insensitive). Unknown: UsageError.
StandardIlluminant parse_standard_illuminant(std::string_view name);

// XYZ of the illuminant with the CIE 1931 observer, scaled to Y = 1 (1 nm trapezoid over
// the whole 360–830 nm CMF table, as CIE 15:2004 §7.1 computes white points). D65 gives (0.95047, 1, 1.08883) — the ASTM E308 white, which
// differs in the 4th decimal from xy_to_XYZ(kWhiteD65) (see chromaticity.h).
Vec3d illuminant_white_xyz(StandardIlluminant illuminant);

// CIE fluorescent illuminant FL`number` (1–12; CIE 015:2018 Table 10.1, the F1–F12 of
// older texts), 380–780 nm at 1 nm. Other numbers: UsageError.
const DenseSpectrum& fluorescent_illuminant(int number);

// An illuminant SPD with chromaticity exactly `white`, for whites with no tabulated CIE
// SPD (the ACES white). It is D65 multiplied by a smooth tilt exp(a·t + b·t²),
// t = (λ − 560 nm)/100 nm, with (a, b) found by Newton's method on the chromaticity.
// The tilt keeps D65's spectral structure; for the ACES white (≈ 6000 K) the factor
// stays within ±15 % over the visible range. Throws UsageError if Newton fails.
DenseSpectrum illuminant_with_chromaticity(Chromaticity white);

// The SPD Prism fits and integrates reflectances under for a space with white `white`:
// the tabulated D65, D50 or E when `white` is one of them (within 1e-4 in xy, the
// rounding of the printed chromaticities), otherwise illuminant_with_chromaticity(white).
DenseSpectrum illuminant_for_white(Chromaticity white);

}  // namespace prism::color
