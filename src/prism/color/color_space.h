#pragma once
// RGB colour spaces defined by the xy chromaticities of three primaries and a white, with
// RGB↔XYZ matrices derived from them (Lindbloom, "RGB/XYZ Matrices",
// brucelindbloom.com; SMPTE RP 177-1993). No matrix is pasted in: every one is computed.
//
// White-point convention (applies to every named space):
//   rgb_to_xyz maps RGB (1, 1, 1) to xy_to_XYZ(white, 1.0), the white's XYZ at Y = 1
//   computed from the xy pair as the defining standard prints it. For sRGB that is
//   (0.95045593, 1, 1.08905775) and the first row is 0.4123908 0.3575843 0.1804808,
//   which rounds to IEC 61966-2-1's printed 0.4124 0.3576 0.1805. Lindbloom's tables use
//   the ASTM E308 white (0.95047, 1, 1.08883) instead; rgb_to_xyz_matrix() accepts any XYZ
//   white and reproduces his 0.4124564 0.3575761 0.1804375 when given that one.
//   ACES (S-2014-004) uses the same convention as ours, so AP0/AP1 match it to 10 digits.
//
// Named spaces (see color_space_names() and docs/color.md):
//   srgb        ITU-R BT.709 primaries, D65            (aliases: rec709, bt709, sRGB)
//   display-p3  SMPTE EG 432-1 P3 primaries, D65       (p3, p3-d65)
//   dci-p3      SMPTE RP 431-2 P3 primaries, DCI white (p3-dci)
//   adobe-rgb   Adobe RGB (1998), D65                  (adobe-rgb-1998, adobergb)
//   rec2020     ITU-R BT.2020 primaries, D65           (bt2020, rec.2020)
//   aces2065-1  ACES AP0 primaries, ACES white         (ap0, aces)
//   acescg      ACES AP1 primaries, ACES white         (ap1)
//   xyz         CIE XYZ itself, white D65 (identity matrices; (1,1,1) is not white)
//   xyz-d50     CIE XYZ itself, white D50 (the ICC profile connection space)
// The xyz spaces carry a white only so that conversions know whether to adapt: XYZ data
// "relative to D65" is what a D65 RGB space produces without adaptation.
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/chromaticity.h"
#include "prism/core/mat3.h"

namespace prism::color {

struct ColorSpace {
  std::string name;
  Chromaticity red, green, blue, white;
  Mat3 rgb_to_xyz;  // linear RGB → CIE XYZ (Y = 1 for RGB white), relative to `white`
  Mat3 xyz_to_rgb;  // its inverse
};

// The eight numbers that define a user space: three primaries and a white.
struct Primaries {
  Chromaticity red, green, blue, white;
};

// Throws UsageError when the primaries cannot define an RGB space: non-finite numbers,
// collinear (or coincident) primaries, a white with y <= 0, or a white outside the
// primaries' triangle (RGB white would need a negative amount of some primary).
// Whether chromaticities lie inside the spectral locus is checked by the spectral code.
void validate_primaries(const Primaries& p);

// Lindbloom's derivation for an arbitrary XYZ white (not necessarily Y = 1): the matrix M
// with columns S_i·(x_i, y_i, z_i) such that M·(1,1,1) = white_XYZ. Validates like
// validate_primaries (white is given as XYZ here).
Mat3 rgb_to_xyz_matrix(Chromaticity r, Chromaticity g, Chromaticity b, const Vec3d& white_XYZ);

// A validated space with white XYZ = xy_to_XYZ(white, 1.0).
ColorSpace make_color_space(std::string name, Chromaticity r, Chromaticity g, Chromaticity b,
                            Chromaticity white);
ColorSpace make_color_space(std::string name, const Primaries& p);

// CIE XYZ as a "space": identity matrices, tagged with the white its data is relative to
// (the named xyz spaces; XYZ relative to E is the spectral film's, and Radiance's XYZE).
ColorSpace xyz_space(std::string name, Chromaticity white);

// XYZ of the space's white at Y = 1 (the adaptation source/destination white).
inline Vec3d white_XYZ(const ColorSpace& space) { return xy_to_XYZ(space.white); }

// A named space, case-insensitive, aliases accepted. Unknown name: UsageError listing the
// canonical names.
const ColorSpace& color_space(std::string_view name);

// Canonical names of the named spaces, in a fixed order.
std::vector<std::string> color_space_names();

// A named space, or a user space written as "xy:rx,ry,gx,gy,bx,by,wx,wy" (eight numbers,
// for example a monitor's measured primaries). Malformed or degenerate: UsageError.
ColorSpace parse_color_space(std::string_view spec);

// Whether a colour just converted into a space's RGB lies outside its gamut: a component
// below 0 by more than the conversion's round-off in float data (1e-5 of the largest
// component; a neutral converted between spaces of one white lands there, not at 0).
inline bool is_outside_gamut(const Vec3d& rgb) { return min_component(rgb) < -1e-5 * max_component(rgb); }

}  // namespace prism::color
