#pragma once
// Chromatic adaptation transforms (von Kries-type: scale cone-like responses by the ratio
// of destination to source white) and the composite RGB→RGB conversion between spaces.
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/core/mat3.h"
#include "prism/core/vec.h"

namespace prism::color {

enum class Cat {
  bradford,     // Lam 1985 / Hunt; the linearised Bradford of ICC.1 Annex E (default)
  cat02,        // CIECAM02 (CIE 159:2004) M_CAT02
  von_kries,    // Hunt–Pointer–Estévez cone fundamentals, normalised to D65
  xyz_scaling,  // scale X, Y, Z directly (the "wrong von Kries" transform)
};

// The 3×3 "cone response" matrix M_A of a transform (identity for xyz_scaling).
Mat3 cat_cone_matrix(Cat cat);

// M = M_A⁻¹ · diag(M_A·dst / M_A·src) · M_A: maps XYZ seen under src_white_XYZ to the
// corresponding XYZ under dst_white_XYZ (Lindbloom, "Chromatic Adaptation"). The whites'
// Y need not be 1; their ratio then also scales luminance. Non-positive cone responses:
// UsageError.
Mat3 adaptation_matrix(const Vec3d& src_white_XYZ, const Vec3d& dst_white_XYZ, Cat cat = Cat::bradford);

// One 3×3 matrix taking linear RGB in `from` to linear RGB in `to`:
//   to.xyz_to_rgb · adaptation(white_XYZ(from) → white_XYZ(to)) · from.rgb_to_xyz,
// where the adaptation is omitted when both whites have the same xy.
Mat3 conversion_matrix(const ColorSpace& from, const ColorSpace& to, Cat cat = Cat::bradford);

// Parses "bradford", "cat02", "von-kries" (alias "hpe") and "xyz-scaling" (alias
// "scaling"); case-insensitive, '_' accepted for '-'. Unknown name: UsageError.
Cat parse_cat(std::string_view name);
std::string_view cat_name(Cat cat);
std::vector<std::string> cat_names();

}  // namespace prism::color
