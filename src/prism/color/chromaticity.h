#pragma once
// CIE 1931 xy chromaticity coordinates, the conversion to and from XYZ, and the white
// points that Prism's named colour spaces are defined with.
//
// White-point convention: every white below is the xy pair exactly as the defining
// standard prints it, and its XYZ is xy_to_XYZ(white, 1.0). For D65 this gives
// (0.95045593, 1, 1.08905775), not the ASTM E308 / Lindbloom table value
// (0.95047, 1, 1.08883) that is integrated from the tabulated D65 SPD (xy ≈ 0.31271,
// 0.32902). See docs/color.md.
#include <cmath>

#include "prism/core/error.h"
#include "prism/core/vec.h"

namespace prism::color {

struct Chromaticity {
  double x, y;
};

// CIE standard illuminant D65 as IEC 61966-2-1 (sRGB) and ITU-R BT.709/BT.2020 print it.
inline constexpr Chromaticity kWhiteD65{0.3127, 0.3290};
// CIE standard illuminant D50 (ICC profile connection space white, ISO 3664).
inline constexpr Chromaticity kWhiteD50{0.3457, 0.3585};
// ACES white, SMPTE ST 2065-1 §4.1 / Academy TB-2014-004: close to, but not, CIE D60
// (CIE D60 is x ≈ 0.32163, y ≈ 0.33774 from the daylight locus at 6000 K × 1.4388/1.438).
inline constexpr Chromaticity kWhiteAces{0.32168, 0.33767};
// Equal-energy illuminant E.
inline constexpr Chromaticity kWhiteE{1.0 / 3, 1.0 / 3};
// DCI-P3 projector white (SMPTE RP 431-2), a greenish white, not a CIE illuminant.
inline constexpr Chromaticity kWhiteDci{0.314, 0.351};

// XYZ of the colour with chromaticity c and luminance Y (CIE 15:2004 eq. 7.3 inverted).
// A chromaticity with y = 0 has no finite XYZ at non-zero luminance: UsageError.
inline Vec3d xy_to_XYZ(Chromaticity c, double Y = 1.0) {
  if (!(c.y != 0.0) || !std::isfinite(c.x) || !std::isfinite(c.y))
    throw UsageError("chromaticity (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                     ") has no XYZ: y must be finite and non-zero");
  return {c.x * Y / c.y, Y, (1.0 - c.x - c.y) * Y / c.y};
}

// Chromaticity of an XYZ triple (CIE 15:2004 eq. 7.3). X + Y + Z = 0 has none: UsageError.
inline Chromaticity XYZ_to_xy(const Vec3d& XYZ) {
  const double sum = XYZ.x + XYZ.y + XYZ.z;
  if (!(sum != 0.0) || !std::isfinite(sum))
    throw UsageError("XYZ with X + Y + Z = 0 has no chromaticity");
  return {XYZ.x / sum, XYZ.y / sum};
}

}  // namespace prism::color
