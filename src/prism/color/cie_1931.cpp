// Lookup into the embedded CIE 1931 2° table (data/cie/cie1931_2deg_xyz_360_830_1nm.csv).
#include "prism/color/cie_1931.h"

#include <algorithm>
#include <cmath>

#include "prism/color/tabulated_data.h"

namespace prism::color {

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
