// Chromatic adaptation and composite conversions against published matrices.
#include "prism/color/chromatic_adaptation.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/published_values.h"

namespace prism::color {
namespace {

// Tolerances (half a unit of the last published digit, or 1e-12 for exact properties) and
// the matrix check: support/published_values.h.
using test::expect_matrix_near;
using test::kExact;
using test::kHalf10;
using test::kHalf7;

// Lindbloom's reference whites (ASTM E308), as used in his adaptation tables.
const Vec3d kLindbloomD65{0.95047, 1.0, 1.08883};
const Vec3d kLindbloomD50{0.96422, 1.0, 0.82521};

TEST(ColorAdaptation, BradfordConeMatrixIsTheIccOne) {
  const Mat3 m = cat_cone_matrix(Cat::bradford);
  EXPECT_EQ(m(0, 0), 0.8951);
  EXPECT_EQ(m(0, 1), 0.2664);
  EXPECT_EQ(m(0, 2), -0.1614);
  EXPECT_EQ(m(1, 1), 1.7135);
  EXPECT_EQ(m(2, 2), 1.0296);
}

// CIE 159:2004 (CIECAM02) eq. 7, M_CAT02 as printed (4 decimals). The values are stored
// exactly as published, so compare all nine elements for equality: any typo, transposition
// or row swap fails.
TEST(ColorAdaptation, Cat02ConeMatrixIsTheCiecam02One) {
  const double published[3][3] = {{0.7328, 0.4296, -0.1624},
                                  {-0.7036, 1.6975, 0.0061},
                                  {0.0030, 0.0136, 0.9834}};
  const Mat3 m = cat_cone_matrix(Cat::cat02);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(m(i, j), published[i][j]) << "element " << i << "," << j;
  // Each row of M_CAT02 sums to 1 (CIECAM02 normalises the sharpened responses so that the
  // equal-energy white E has R = G = B = Y); the printed 4-decimal values keep that exactly.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m(i, 0) + m(i, 1) + m(i, 2), 1.0, kExact) << "row " << i;
}

// Lindbloom, "Chromatic Adaptation", D65 → D50 tables, 7 decimals.
TEST(ColorAdaptation, ReproducesLindbloomD65ToD50) {
  const double bradford[3][3] = {{1.0478112, 0.0228866, -0.0501270},
                                 {0.0295424, 0.9904844, -0.0170491},
                                 {-0.0092345, 0.0150436, 0.7521316}};
  expect_matrix_near(adaptation_matrix(kLindbloomD65, kLindbloomD50, Cat::bradford), bradford, kHalf7);
  const double von_kries[3][3] = {{1.0160803, 0.0552297, -0.0521326},
                                  {0.0060666, 0.9955661, -0.0012235},
                                  {0.0, 0.0, 0.7578869}};
  expect_matrix_near(adaptation_matrix(kLindbloomD65, kLindbloomD50, Cat::von_kries), von_kries, kHalf7);
  const double scaling[3][3] = {{1.0144665, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 0.7578869}};
  expect_matrix_near(adaptation_matrix(kLindbloomD65, kLindbloomD50, Cat::xyz_scaling), scaling, kHalf7);
}

// CSS Color 4 §"Sample code for color conversions" (csswg-drafts css-color-4/conversions.js,
// D65_to_D50): Bradford with whites from xy (0.3127, 0.3290) and (0.3457, 0.3585), printed
// to full double precision. (Earlier drafts printed 1.0479298208405488...: those used
// Lindbloom's rounded inverse cone matrix and differ from an exact derivation by ~5e-8.)
TEST(ColorAdaptation, ReproducesCssColor4BradfordFromXyWhites) {
  const double css[3][3] = {{1.0479297925449969, 0.022946870601609652, -0.05019226628920524},
                            {0.02962780877005599, 0.9904344267538799, -0.017073799063418826},
                            {-0.009243040646204504, 0.015055191490298152, 0.7518742814281371}};
  expect_matrix_near(adaptation_matrix(xy_to_XYZ(kWhiteD65), xy_to_XYZ(kWhiteD50)), css, kExact);
}

TEST(ColorAdaptation, EveryTransformMapsSourceWhiteToDestinationWhite) {
  for (Cat cat : {Cat::bradford, Cat::cat02, Cat::von_kries, Cat::xyz_scaling}) {
    SCOPED_TRACE(cat_name(cat));
    const Vec3d src = xy_to_XYZ(kWhiteAces), dst = xy_to_XYZ(kWhiteD65);
    const Vec3d mapped = adaptation_matrix(src, dst, cat) * src;
    EXPECT_NEAR(mapped.x, dst.x, kExact);
    EXPECT_NEAR(mapped.y, dst.y, kExact);
    EXPECT_NEAR(mapped.z, dst.z, kExact);
    const Mat3 same = adaptation_matrix(src, src, cat);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(same(i, j), i == j ? 1.0 : 0.0, kExact);
  }
}

TEST(ColorAdaptation, RejectsWhitesWithoutPositiveConeResponse) {
  EXPECT_THROW(adaptation_matrix({0.0, 0.0, 0.0}, xy_to_XYZ(kWhiteD65)), UsageError);
  EXPECT_THROW(adaptation_matrix(xy_to_XYZ(kWhiteD65), {-1.0, 1.0, 1.0}, Cat::xyz_scaling), UsageError);
}

TEST(ColorConversion, AcesWhiteMapsToSrgbWhite) {
  const Vec3d rgb = conversion_matrix(color_space("acescg"), color_space("srgb")) * Vec3d(1.0);
  EXPECT_NEAR(rgb.x, 1.0, kExact);
  EXPECT_NEAR(rgb.y, 1.0, kExact);
  EXPECT_NEAR(rgb.z, 1.0, kExact);
}

TEST(ColorConversion, WhiteMapsToWhiteBetweenAllRgbSpacesWithEveryCat) {
  const std::vector<std::string> rgb_spaces = {"srgb", "display-p3", "dci-p3", "adobe-rgb",
                                               "rec2020", "aces2065-1", "acescg"};
  for (Cat cat : {Cat::bradford, Cat::cat02, Cat::von_kries, Cat::xyz_scaling})
    for (const auto& from : rgb_spaces)
      for (const auto& to : rgb_spaces) {
        SCOPED_TRACE(from + " -> " + to + " " + std::string(cat_name(cat)));
        const Vec3d rgb = conversion_matrix(color_space(from), color_space(to), cat) * Vec3d(1.0);
        EXPECT_NEAR(rgb.x, 1.0, kExact);
        EXPECT_NEAR(rgb.y, 1.0, kExact);
        EXPECT_NEAR(rgb.z, 1.0, kExact);
      }
}

// S-2014-004 §4.1.4 / AMPAS aces-dev ACEScg↔ACES2065-1: both use the ACES white, so no
// adaptation takes place; 10 decimals.
TEST(ColorConversion, Ap1ToAp0MatchesTheAcademy) {
  const double ap1_to_ap0[3][3] = {{0.6954522414, 0.1406786965, 0.1638690622},
                                   {0.0447945634, 0.8596711185, 0.0955343182},
                                   {-0.0055258826, 0.0040252103, 1.0015006723}};
  const double ap0_to_ap1[3][3] = {{1.4514393161, -0.2365107469, -0.2149285693},
                                   {-0.0765537734, 1.1762296998, -0.0996759264},
                                   {0.0083161484, -0.0060324498, 0.9977163014}};
  expect_matrix_near(conversion_matrix(color_space("acescg"), color_space("aces2065-1")), ap1_to_ap0, kHalf10);
  expect_matrix_near(conversion_matrix(color_space("aces2065-1"), color_space("acescg")), ap0_to_ap1, kHalf10);
}

TEST(ColorConversion, SameWhiteSkipsAdaptationAndXyzSpacesCarryTheirWhite) {
  const ColorSpace& srgb = color_space("srgb");
  const Mat3 to_xyz = conversion_matrix(srgb, color_space("xyz"), Cat::cat02);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(to_xyz(i, j), srgb.rgb_to_xyz(i, j), kExact);
  // sRGB → XYZ relative to D50 is the ICC-style Bradford-adapted matrix.
  const Mat3 to_d50 = conversion_matrix(srgb, color_space("xyz-d50"));
  const Mat3 expected = adaptation_matrix(xy_to_XYZ(kWhiteD65), xy_to_XYZ(kWhiteD50)) * srgb.rgb_to_xyz;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(to_d50(i, j), expected(i, j), kExact);
  const Vec3d white = to_d50 * Vec3d(1.0);
  EXPECT_NEAR(white.x, 0.3457 / 0.3585, kExact);
}

TEST(ColorConversion, RoundTripIsIdentity) {
  const Mat3 there = conversion_matrix(color_space("dci-p3"), color_space("rec2020"), Cat::cat02);
  const Mat3 back = conversion_matrix(color_space("rec2020"), color_space("dci-p3"), Cat::cat02);
  const Mat3 id = back * there;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(id(i, j), i == j ? 1.0 : 0.0, kExact);
}

TEST(ColorAdaptation, ParsesNames) {
  EXPECT_EQ(parse_cat("Bradford"), Cat::bradford);
  EXPECT_EQ(parse_cat("CAT02"), Cat::cat02);
  EXPECT_EQ(parse_cat("von-kries"), Cat::von_kries);
  EXPECT_EQ(parse_cat("von_kries"), Cat::von_kries);
  EXPECT_EQ(parse_cat("hpe"), Cat::von_kries);
  EXPECT_EQ(parse_cat("xyz-scaling"), Cat::xyz_scaling);
  EXPECT_THROW(parse_cat("cat16"), UsageError);
  for (const std::string& name : cat_names()) EXPECT_EQ(cat_name(parse_cat(name)), name);
}

}  // namespace
}  // namespace prism::color
