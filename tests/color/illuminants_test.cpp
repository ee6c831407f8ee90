// Standard illuminant white points against published values, blackbody radiation, and the
// spectrum types.
#include <cmath>

#include <gtest/gtest.h>

#include "prism/color/illuminants.h"
#include "prism/color/spectrum.h"

namespace prism::color {
namespace {

// Published XYZ (Y = 100) of the CIE illuminants with the 1931 observer (ASTM E308 / CIE
// 15:2004 Table T.3; reproduced in data/SOURCES.md §1), printed to 3 decimals, so they
// carry ±0.0005 of rounding. Integrating the same 1 nm tables over 360–830 nm as CIE does
// leaves only that rounding and float summation (~1e-12): bound 0.001.
void expect_white(StandardIlluminant illuminant, double x, double z) {
  const Vec3d xyz = illuminant_white_xyz(illuminant) * 100.0;
  EXPECT_NEAR(xyz.x, x, 0.001);
  EXPECT_DOUBLE_EQ(xyz.y, 100.0);
  EXPECT_NEAR(xyz.z, z, 0.001);
}

TEST(Illuminants, IntegratedWhitePointsMatchPublishedValues) {
  expect_white(StandardIlluminant::d65, 95.047, 108.883);
  expect_white(StandardIlluminant::d50, 96.424, 82.513);
  expect_white(StandardIlluminant::a, 109.850, 35.585);
  const Chromaticity e = XYZ_to_xy(illuminant_white_xyz(StandardIlluminant::e));
  EXPECT_NEAR(e.x, 1.0 / 3.0, 1e-4);  // CIE normalises ∫x̄ = ∫ȳ = ∫z̄ to the table's precision
  EXPECT_NEAR(e.y, 1.0 / 3.0, 1e-4);
}

// CIE 15:2004 Table T.8 prints the fluorescent illuminants' chromaticities (1931 observer)
// to 4 decimals: F2 (0.3721, 0.3751), F7 (0.3129, 0.3292), F11 (0.3805, 0.3769). The 1 nm
// tables integrated over their 380–780 nm give them within the printing's ±0.00005; the
// bound adds as much again for the range (CIE tabulates FL at 5 nm, 380–780, too).
TEST(Illuminants, FluorescentChromaticitiesMatchPublishedValues) {
  const struct {
    int number;
    double x, y;
  } published[] = {{2, 0.3721, 0.3751}, {7, 0.3129, 0.3292}, {11, 0.3805, 0.3769}};
  for (const auto& p : published) {
    const Chromaticity c = XYZ_to_xy(spectrum_to_xyz(fluorescent_illuminant(p.number)));
    EXPECT_NEAR(c.x, p.x, 1e-4) << "FL" << p.number;
    EXPECT_NEAR(c.y, p.y, 1e-4) << "FL" << p.number;
  }
  // The line spectra are there: FL11's 545 nm terbium line stands far above its surroundings.
  const DenseSpectrum& f11 = fluorescent_illuminant(11);
  EXPECT_GT(f11(545.0), 5.0 * f11(530.0));
  EXPECT_THROW(fluorescent_illuminant(0), UsageError);
  EXPECT_THROW(fluorescent_illuminant(13), UsageError);
}

TEST(Illuminants, ParsesNamesAndRejectsUnknownOnes) {
  EXPECT_EQ(parse_standard_illuminant("D65"), StandardIlluminant::d65);
  EXPECT_EQ(parse_standard_illuminant("a"), StandardIlluminant::a);
  EXPECT_THROW(parse_standard_illuminant("d66"), UsageError);
}

TEST(Illuminants, SmoothIlluminantReachesTheAcesWhite) {
  const DenseSpectrum aces = illuminant_with_chromaticity(kWhiteAces);
  const Chromaticity c = XYZ_to_xy(spectrum_to_xyz(aces));
  EXPECT_NEAR(c.x, kWhiteAces.x, 1e-9);
  EXPECT_NEAR(c.y, kWhiteAces.y, 1e-9);
  // The tilt stays gentle: within ±15 % of D65's shape across the visible range.
  const DenseSpectrum& d65 = standard_illuminant(StandardIlluminant::d65);
  const double ratio_560 = aces(560.0) / d65(560.0);
  for (double nm = 380; nm <= 780; nm += 10) EXPECT_NEAR(aces(nm) / d65(nm) / ratio_560, 1.0, 0.15) << nm;
}

TEST(Blackbody, PlanckAndWien) {
  // B_λ(5000 K, 500 nm) = 2hc²/λ⁵/(e^{hc/λkT} − 1) = 1.2107e13 W·m⁻²·sr⁻¹·m⁻¹ (hand-evaluated
  // with CODATA constants) = 1.2107e4 per nm.
  EXPECT_NEAR(planck_radiance(500.0, 5000.0), 1.2107e4, 2.0);
  const BlackbodySpectrum normalized(3000.0, true);
  EXPECT_NEAR(normalized.peak_wavelength_nm(), 965.9, 0.1);
  EXPECT_NEAR(normalized(normalized.peak_wavelength_nm()), 1.0, 1e-12);
  EXPECT_LT(normalized(900.0), 1.0);
  EXPECT_LT(normalized(1030.0), 1.0);
  // Illuminant A is by definition a Planckian radiator of 2856 K (CIE 15:2004 §3.1): same
  // chromaticity within the table's rounding (x = 0.44757, y = 0.40745).
  const Chromaticity a = XYZ_to_xy(spectrum_to_xyz(BlackbodySpectrum(2856.0)));
  EXPECT_NEAR(a.x, 0.44757, 3e-4);
  EXPECT_NEAR(a.y, 0.40745, 3e-4);
  EXPECT_THROW(BlackbodySpectrum(-1.0), UsageError);
}

TEST(Spectra, DenseAndPiecewiseLinearInterpolation) {
  const DenseSpectrum dense(400.0, 10.0, {1.0, 3.0});
  EXPECT_DOUBLE_EQ(dense(405.0), 2.0);
  EXPECT_DOUBLE_EQ(dense(399.0), 0.0);
  // Cornell box white wall, first three measured points (400, 404, 408 nm; see ../shared
  // scenes/cornell_box/cornell_measured): interpolated between, held beyond the ends.
  const PiecewiseLinearSpectrum wall({400.0, 404.0, 408.0}, {0.343, 0.445, 0.551});
  EXPECT_DOUBLE_EQ(wall(402.0), 0.5 * (0.343 + 0.445));
  EXPECT_DOUBLE_EQ(wall(380.0), 0.343);
  EXPECT_DOUBLE_EQ(wall(700.0), 0.551);
  EXPECT_THROW(PiecewiseLinearSpectrum({400.0, 400.0}, {1.0, 2.0}), UsageError);
  EXPECT_THROW(PiecewiseLinearSpectrum({400.0}, {1.0, 2.0}), UsageError);
}

TEST(Spectra, LuminanceUses683LumensPerWatt) {
  // A flat 1 W·m⁻²·sr⁻¹·nm⁻¹ radiance has luminance 683 · ∫ȳ.
  EXPECT_NEAR(luminance_nits(ConstantSpectrum{1.0}), 683.0 * cie1931_y_integral(), 1e-9);
}

}  // namespace
}  // namespace prism::color
