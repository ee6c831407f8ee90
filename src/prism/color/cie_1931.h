#pragma once
// The CIE 1931 2° standard observer (CIE 018:2019, tabulated at 1 nm) and the photometric
// constants that turn its ȳ integral into luminance.
#include "prism/core/vec.h"

namespace prism::color {

// The visible range Prism samples and integrates over. The CMFs outside it contribute
// ~1e-4 of ∫ȳ, below anything a renderer resolves.
inline constexpr double kVisibleMinNm = 380.0;
inline constexpr double kVisibleMaxNm = 780.0;
inline constexpr double kVisibleRangeNm = kVisibleMaxNm - kVisibleMinNm;

// Maximum luminous efficacy of radiation at 555 nm (SI definition of the candela): lm/W.
inline constexpr double kMaxLuminousEfficacyLmPerW = 683.0;

// x̄, ȳ, z̄ at `wavelength_nm`, linearly interpolated between the 1 nm table entries; zero
// outside the tabulated 360–830 nm.
Vec3d cie1931_xyz_bar(double wavelength_nm);
double cie1931_y_bar(double wavelength_nm);

// ∫ȳ dλ over [380, 780] nm by the trapezoid rule at 1 nm (≈ 106.857): the Y of a flat
// spectrum of value 1, used to normalise reflectance-style integrals.
double cie1931_y_integral();

}  // namespace prism::color
