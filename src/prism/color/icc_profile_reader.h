#pragma once
// Reading the matrix/TRC model of an ICC profile (ICC.1:2022, profile versions 2 and 4):
// for an RGB profile three tone curves (rTRC, gTRC, bTRC) and three colorants (rXYZ,
// gXYZ, bXYZ) in the profile connection space, CIE XYZ relative to D50; for a grey one the
// grey tone curve (kTRC). It is the model of every display and working-space profile
// (sRGB, Display P3, Adobe RGB, Rec.2020, ProPhoto) that images embed. Profiles built of
// lookup tables alone (A2B0 without the matrix/TRC tags, as printer and camera profiles
// are) are not read: they are refused with the reason, and the caller says what it did.
//
// Where a profile has both, the matrix/TRC tags are used (the colorimetric model of a
// display profile; a CMM would take the A2B tables for some rendering intents).
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "prism/core/mat3.h"

namespace prism::color {

// One of a profile's tone curves, from device code in [0, 1] to linear light in [0, 1]:
// curveType (ICC.1 §10.6: no entries is the identity, one entry a gamma in u8Fixed8, more
// a table over equally spaced codes, interpolated linearly) or parametricCurveType (§10.18,
// functions 0 to 4).
struct IccCurve {
  enum class Kind : std::uint8_t { identity, gamma, table, parametric };
  Kind kind = Kind::identity;
  double gamma = 1.0;
  std::vector<double> table;       // Kind::table, entries / 65535
  int function = 0;                // Kind::parametric: 0 to 4
  std::array<double, 7> params{};  // g, a, b, c, d, e, f as §10.18 names them
  double operator()(double code) const;
};

struct IccMatrixTrc {
  bool gray = false;               // a grey profile: curves[0] alone
  Mat3 colorants{};                // RGB → PCS XYZ (D50): columns rXYZ, gXYZ, bXYZ
  std::array<IccCurve, 3> curves;  // r, g, b
  std::string description;         // the 'desc' tag's text (ASCII), or "" without one
};

// Throws Error with the reason ("not an ICC profile", "a CMYK profile", "no rXYZ tag (a
// profile of lookup tables only)", "its rTRC tag runs past the profile's end", ...) when
// `profile` is not a well-formed matrix/TRC profile.
IccMatrixTrc read_icc_matrix_trc(std::span<const std::uint8_t> profile);

}  // namespace prism::color
