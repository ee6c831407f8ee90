// CIE 1931 table lookup against values printed in CIE 018:2019, and the Wyman–Sloan–
// Shirley 2013 analytic fit's error against that table.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "prism/color/cie_1931.h"
#include "prism/color/cie_1931_wyman.h"

namespace prism::color {
namespace {

TEST(Cie1931, TabulatedValuesMatchThePublishedTable) {
  // Exact table entries: CIE 018:2019 1 nm table (see data/SOURCES.md spot values).
  EXPECT_DOUBLE_EQ(cie1931_xyz_bar(555.0).y, 1.0);
  EXPECT_DOUBLE_EQ(cie1931_xyz_bar(600.0).x, 1.0622);
  EXPECT_DOUBLE_EQ(cie1931_xyz_bar(450.0).z, 1.77211);
  EXPECT_DOUBLE_EQ(cie1931_xyz_bar(455.0).z, 1.7441);
}

TEST(Cie1931, InterpolatesLinearlyAndIsZeroOutsideTheTable) {
  const Vec3d a = cie1931_xyz_bar(600.0), b = cie1931_xyz_bar(601.0), mid = cie1931_xyz_bar(600.25);
  EXPECT_NEAR(mid.x, 0.75 * a.x + 0.25 * b.x, 1e-15);
  EXPECT_EQ(cie1931_xyz_bar(359.9), Vec3d{});
  EXPECT_EQ(cie1931_xyz_bar(830.1), Vec3d{});
  EXPECT_GT(cie1931_xyz_bar(830.0).x, 0.0);
}

TEST(Cie1931, YIntegralOverTheVisibleRange) {
  // ∫ȳ over 360–830 nm is 106.856895 (CIE 15:2004, k = 683/106.857 lm/W for E); the
  // 380–780 nm part we integrate over misses ~1e-4 of it in the tails.
  EXPECT_NEAR(cie1931_y_integral(), 106.857, 0.02);
}

TEST(Cie1931Wyman, MultiLobeFitErrorAgainstTheTable) {
  Vec3d max_error{};
  Vec3d worst_nm{};
  for (int nm = 380; nm <= 780; ++nm) {
    const Vec3d diff = cie1931_xyz_bar_wyman(nm) - cie1931_xyz_bar(nm);
    for (int c = 0; c < 3; ++c)
      if (std::abs(diff[c]) > max_error[c]) {
        max_error[c] = std::abs(diff[c]);
        worst_nm[c] = nm;
      }
  }
  std::printf("Wyman-Sloan-Shirley 2013 multi-lobe fit, max |fit - CIE 1931 table| over 380-780 nm:\n"
              "  x: %.5f at %g nm, y: %.5f at %g nm, z: %.5f at %g nm\n",
              max_error.x, worst_nm.x, max_error.y, worst_nm.y, max_error.z, worst_nm.z);
  // JCGT 2(2) presents eq. 4 as accurate to within the spread of the observer data behind
  // the CIE standard, its plots showing errors of a few hundredths at most, at the lobe
  // flanks (the CMFs peak at 1.06, 1.0 and 1.78). We measure 0.0149 (x̄, 631 nm), 0.0076
  // (ȳ, 528 nm) and 0.0238 (z̄, 425 nm), consistent with that claim (a few % of the
  // peaks, the order of the inter-observer spread). Bound 0.03, i.e. ≤ 3 % of each peak:
  // the measured maximum with 25 % headroom, so the test pins the fit's documented
  // accuracy and catches gross transcription errors (a wrong lobe mean or width).
  EXPECT_LT(max_error.x, 0.03);
  EXPECT_LT(max_error.y, 0.03);
  EXPECT_LT(max_error.z, 0.03);
}

}  // namespace
}  // namespace prism::color
