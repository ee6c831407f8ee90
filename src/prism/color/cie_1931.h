#pragma once
// The CIE 1931 2° standard observer (CIE 018:2019, tabulated at 1 nm) and the photometric
// constants that turn its ȳ integral into luminance.
#include <algorithm>

#include "prism/color/tabulated_data.h"
#include "prism/core/vec.h"

namespace prism::color {

// The visible range Prism samples and integrates over. The CMFs outside it contribute
// ~1e-4 of ∫ȳ, below anything a renderer resolves.
inline constexpr double kVisibleMinNm = 380.0;
inline constexpr double kVisibleMaxNm = 780.0;
inline constexpr double kVisibleRangeNm = kVisibleMaxNm - kVisibleMinNm;

// Maximum luminous efficacy of radiation at 555 nm (SI definition of the candela): lm/W.
inline constexpr double kMaxLuminousEfficacyLmPerW = 683.0;

namespace detail {
// wavelength_nm, x̄, ȳ, z̄ per row, 360–830 nm at 1 nm (one object for the whole program).
inline const data::Table& cie1931_table() {
  static const data::Table table = data::cie1931_2deg_xyz();
  return table;
}
}  // namespace detail

// x̄, ȳ, z̄ at `wavelength_nm` from `table` (the one detail::cie1931_table() returns),
// linearly interpolated between its 1 nm entries; zero outside the tabulated 360–830 nm.
// Inline: the film calls it for every wavelength of every path sample, and fetches the
// table once per sample (each fetch's static-guard check and loads would otherwise repeat
// for every wavelength).
inline Vec3d cie1931_xyz_bar(const data::Table& table, double wavelength_nm) {
  const double first_nm = table.at(0, 0);
  const double offset = wavelength_nm - first_nm;  // the table is at exactly 1 nm steps
  if (!(offset >= 0.0) || offset > table.rows - 1) return {};
  const int i = std::min(static_cast<int>(offset), table.rows - 2);
  const double t = offset - i;
  auto row = [&](int r) { return Vec3d{table.at(r, 1), table.at(r, 2), table.at(r, 3)}; };
  return row(i) * (1.0 - t) + row(i + 1) * t;
}
// The same, for a caller that looks up one wavelength.
inline Vec3d cie1931_xyz_bar(double wavelength_nm) { return cie1931_xyz_bar(detail::cie1931_table(), wavelength_nm); }
double cie1931_y_bar(double wavelength_nm);

// ∫ȳ dλ over [380, 780] nm by the trapezoid rule at 1 nm (≈ 106.857): the Y of a flat
// spectrum of value 1, used to normalise reflectance-style integrals.
double cie1931_y_integral();

}  // namespace prism::color
