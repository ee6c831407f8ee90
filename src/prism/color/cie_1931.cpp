// Lookup into the embedded CIE 1931 2° table (data/cie/cie1931_2deg_xyz_360_830_1nm.csv).
#include "prism/color/cie_1931.h"

#include <algorithm>
#include <cmath>

#include "prism/color/tabulated_data.h"

namespace prism::color {

Vec3d cie1931_xyz_bar(double wavelength_nm) {
  static const data::Table table = data::cie1931_2deg_xyz();
  const double first_nm = table.at(0, 0);
  const double offset = wavelength_nm - first_nm;  // the table is at exactly 1 nm steps
  if (!(offset >= 0.0) || offset > table.rows - 1) return {};
  const int i = std::min(static_cast<int>(offset), table.rows - 2);
  const double t = offset - i;
  auto row = [&](int r) { return Vec3d{table.at(r, 1), table.at(r, 2), table.at(r, 3)}; };
  return row(i) * (1.0 - t) + row(i + 1) * t;
}

double cie1931_y_bar(double wavelength_nm) { return cie1931_xyz_bar(wavelength_nm).y; }

double cie1931_y_integral() {
  static const double integral = [] {
    double sum = 0.0;
    for (int nm = static_cast<int>(kVisibleMinNm); nm <= static_cast<int>(kVisibleMaxNm); ++nm) {
      const double weight = (nm == kVisibleMinNm || nm == kVisibleMaxNm) ? 0.5 : 1.0;
      sum += weight * cie1931_y_bar(nm);
    }
    return sum;
  }();
  return integral;
}

}  // namespace prism::color
