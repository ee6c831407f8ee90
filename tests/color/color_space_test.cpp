// Colour spaces: derived matrices against published ones, validation, name lookup.
#include "prism/color/color_space.h"
#include "prism/color/chromatic_adaptation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <string>

#include "support/published_values.h"

namespace prism::color {
namespace {

// Tolerances (half a unit of the last published digit, or 1e-12 for exact properties) and
// the matrix check: support/published_values.h.
using test::expect_matrix_near;
using test::kExact;
using test::kHalf10;
using test::kHalf7;

constexpr Chromaticity kR709{0.64, 0.33}, kG709{0.30, 0.60}, kB709{0.15, 0.06};

TEST(ColorSpace, XyToXyzOfD65UsesThePrintedChromaticity) {
  const Vec3d w = xy_to_XYZ(kWhiteD65);
  EXPECT_NEAR(w.x, 0.3127 / 0.3290, kExact);
  EXPECT_EQ(w.y, 1.0);
  EXPECT_NEAR(w.z, (1 - 0.3127 - 0.3290) / 0.3290, kExact);
  const Chromaticity back = XYZ_to_xy(w * 42.0);
  EXPECT_NEAR(back.x, 0.3127, kExact);
  EXPECT_NEAR(back.y, 0.3290, kExact);
  EXPECT_THROW(xy_to_XYZ({0.3, 0.0}), UsageError);
}

// Lindbloom, "RGB/XYZ Matrices" (brucelindbloom.com), sRGB with his D65 reference white
// X = 0.95047, Y = 1, Z = 1.08883 (ASTM E308), printed to 7 decimals.
TEST(ColorSpace, ReproducesLindbloomSrgbWithHisWhite) {
  const Mat3 m = rgb_to_xyz_matrix(kR709, kG709, kB709, {0.95047, 1.0, 1.08883});
  const double lindbloom[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                  {0.2126729, 0.7151522, 0.0721750},
                                  {0.0193339, 0.1191920, 0.9503041}};
  expect_matrix_near(m, lindbloom, kHalf7);
  const double lindbloom_inverse[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                          {-0.9692660, 1.8760108, 0.0415560},
                                          {0.0556434, -0.2040259, 1.0572252}};
  expect_matrix_near(inverse(m), lindbloom_inverse, kHalf7);
}

// Named sRGB uses the white computed from xy (0.3127, 0.3290). IEC 61966-2-1:1999 §5.2
// prints its matrix to 4 decimals (half-unit: 0.5e-4); CSS Color 4 §"Sample code for
// predefined color spaces" gives the same convention's matrix as exact rationals.
TEST(ColorSpace, NamedSrgbMatchesIecAndCssColor4) {
  const ColorSpace& s = color_space("srgb");
  const double iec[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
  expect_matrix_near(s.rgb_to_xyz, iec, 0.5e-4);
  const double css[3][3] = {{506752.0 / 1228815, 87881.0 / 245763, 12673.0 / 70218},
                            {87098.0 / 409605, 175762.0 / 245763, 12673.0 / 175545},
                            {7918.0 / 409605, 87881.0 / 737289, 1001167.0 / 1053270}};
  expect_matrix_near(s.rgb_to_xyz, css, kExact);
}

// CSS Color 4 exact rationals for Display P3 (D65).
TEST(ColorSpace, NamedDisplayP3MatchesCssColor4) {
  const double css[3][3] = {{608311.0 / 1250200, 189793.0 / 714400, 198249.0 / 1000160},
                            {35783.0 / 156275, 247089.0 / 357200, 198249.0 / 2500400},
                            {0.0, 32229.0 / 714400, 5220557.0 / 5000800}};
  expect_matrix_near(color_space("display-p3").rgb_to_xyz, css, kExact);
}

// ACES S-2014-004 §4.1.3 and SMPTE ST 2065-1 §4.2.3, printed to 10 decimals.
TEST(ColorSpace, AcesMatricesMatchTheAcademyToTenDecimals) {
  const double ap0_to_xyz[3][3] = {{0.9525523959, 0.0, 0.0000936786},
                                   {0.3439664498, 0.7281660966, -0.0721325464},
                                   {0.0, 0.0, 1.0088251844}};
  const double xyz_to_ap0[3][3] = {{1.0498110175, 0.0, -0.0000974845},
                                   {-0.4959030231, 1.3733130458, 0.0982400361},
                                   {0.0, 0.0, 0.9912520182}};
  const double ap1_to_xyz[3][3] = {{0.6624541811, 0.1340042065, 0.1561876870},
                                   {0.2722287168, 0.6740817658, 0.0536895174},
                                   {-0.0055746495, 0.0040607335, 1.0103391003}};
  const double xyz_to_ap1[3][3] = {{1.6410233797, -0.3248032942, -0.2364246952},
                                   {-0.6636628587, 1.6153315917, 0.0167563477},
                                   {0.0117218943, -0.0082844420, 0.9883948585}};
  expect_matrix_near(color_space("aces2065-1").rgb_to_xyz, ap0_to_xyz, kHalf10);
  expect_matrix_near(color_space("aces2065-1").xyz_to_rgb, xyz_to_ap0, kHalf10);
  expect_matrix_near(color_space("acescg").rgb_to_xyz, ap1_to_xyz, kHalf10);
  expect_matrix_near(color_space("acescg").xyz_to_rgb, xyz_to_ap1, kHalf10);
}

// For every named RGB space: RGB white maps to the white's XYZ at Y = 1, the Y row sums
// to 1, and the two matrices are inverses.
TEST(ColorSpace, EveryNamedSpaceMapsWhiteToWhiteAndInverts) {
  for (const std::string& name : color_space_names()) {
    SCOPED_TRACE(name);
    const ColorSpace& s = color_space(name);
    EXPECT_EQ(s.name, name);
    const Mat3 id = s.rgb_to_xyz * s.xyz_to_rgb;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(id(i, j), i == j ? 1.0 : 0.0, kExact);
    if (name.rfind("xyz", 0) == 0) continue;  // XYZ "spaces" are identity: (1,1,1) is E
    const Vec3d w = s.rgb_to_xyz * Vec3d(1.0);
    const Vec3d expected = xy_to_XYZ(s.white);
    EXPECT_NEAR(w.x, expected.x, kExact);
    EXPECT_NEAR(w.y, 1.0, kExact);
    EXPECT_NEAR(w.z, expected.z, kExact);
  }
}

TEST(ColorSpace, NamesAreCanonicalAndComplete) {
  const std::vector<std::string> expected = {"srgb",       "display-p3", "dci-p3", "adobe-rgb", "rec2020",
                                             "aces2065-1", "acescg",     "xyz",    "xyz-d50"};
  EXPECT_EQ(color_space_names(), expected);
}

TEST(ColorSpace, LookupIsCaseInsensitiveWithAliases) {
  EXPECT_EQ(color_space("sRGB").name, "srgb");
  EXPECT_EQ(color_space("Rec709").name, "srgb");
  EXPECT_EQ(color_space("P3").name, "display-p3");
  EXPECT_EQ(color_space("p3-dci").name, "dci-p3");
  EXPECT_EQ(color_space("AdobeRGB").name, "adobe-rgb");
  EXPECT_EQ(color_space("BT2020").name, "rec2020");
  EXPECT_EQ(color_space("AP0").name, "aces2065-1");
  EXPECT_EQ(color_space("ap1").name, "acescg");
  EXPECT_EQ(color_space("ACEScg").name, "acescg");
  EXPECT_EQ(color_space("XYZ_D50").name, "xyz-d50");
  EXPECT_EQ(color_space("ciexyz").name, "xyz");
}

TEST(ColorSpace, UnknownNameListsTheValidOnes) {
  try {
    (void)color_space("prophoto");
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("prophoto"), std::string::npos);
    for (const std::string& name : color_space_names()) EXPECT_NE(what.find(name), std::string::npos) << name;
  }
}

TEST(ColorSpace, ValidationRejectsDegeneratePrimaries) {
  const Primaries ok{kR709, kG709, kB709, kWhiteD65};
  EXPECT_NO_THROW(validate_primaries(ok));
  Primaries collinear = ok;
  collinear.green = {0.395, 0.195};  // midpoint of red and blue
  EXPECT_THROW(validate_primaries(collinear), UsageError);
  Primaries coincident = ok;
  coincident.blue = coincident.red;
  EXPECT_THROW(validate_primaries(coincident), UsageError);
  Primaries white_outside = ok;
  white_outside.white = {0.6, 0.6};
  EXPECT_THROW(validate_primaries(white_outside), UsageError);
  Primaries white_on_edge = ok;
  white_on_edge.white = {0.395, 0.195};
  EXPECT_THROW(validate_primaries(white_on_edge), UsageError);
  Primaries white_zero_y = ok;
  white_zero_y.white = {0.3, 0.0};
  EXPECT_THROW(validate_primaries(white_zero_y), UsageError);
  Primaries not_finite = ok;
  not_finite.red.x = std::nan("");
  EXPECT_THROW(validate_primaries(not_finite), UsageError);
  EXPECT_THROW(make_color_space("bad", collinear), UsageError);
}

TEST(ColorSpace, ClockwisePrimariesAndNegativeYPrimariesAreValid) {
  // AP0's blue has y < 0; the order of primaries does not matter to the derivation.
  EXPECT_NO_THROW(validate_primaries({{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}, kWhiteAces}));
  const ColorSpace swapped = make_color_space("swapped", kB709, kG709, kR709, kWhiteD65);
  const Mat3& srgb = color_space("srgb").rgb_to_xyz;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(swapped.rgb_to_xyz(i, 0), srgb(i, 2), kExact);
}

TEST(ColorSpace, ParsesUserPrimaries) {
  const ColorSpace user = parse_color_space("xy:0.64,0.33,0.30,0.60,0.15,0.06,0.3127,0.3290");
  const Mat3& srgb = color_space("srgb").rgb_to_xyz;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(user.rgb_to_xyz(i, j), srgb(i, j), kExact);
  EXPECT_EQ(parse_color_space("ACEScg").name, "acescg");
  EXPECT_THROW(parse_color_space("xy:0.64,0.33"), UsageError);
  EXPECT_THROW(parse_color_space("xy:0.64,0.33,0.30,0.60,0.15,0.06,0.3127,0.3290,1"), UsageError);
  EXPECT_THROW(parse_color_space("xy:0.64,0.33,0.30,0.60,0.15,0.06,0.3127,abc"), UsageError);
  EXPECT_THROW(parse_color_space("xy:0.64,0.33,0.30,0.60,0.15,0.06,0.3127,"), UsageError);
  EXPECT_THROW(parse_color_space("xy:0.64,0.33,0.64,0.33,0.15,0.06,0.3127,0.3290"), UsageError);
  EXPECT_THROW(parse_color_space("nonsense"), UsageError);
}

// A colour converted into a space is outside its gamut when a component is negative beyond
// float data's round-off: Rec.709's primaries and white stored as float ACEScg (a file's
// numbers) come back to Rec.709 inside, an ACEScg red that Rec.709 cannot hold does not,
// and a colour 2e-5 of its largest component below 0 is outside while 0.5e-5 is not.
TEST(ColorSpace, OutsideGamutMeansNegativeBeyondRoundOff) {
  const Mat3 to_acescg = conversion_matrix(color_space("srgb"), color_space("acescg"));
  const Mat3 to_srgb = conversion_matrix(color_space("acescg"), color_space("srgb"));
  for (const Vec3d srgb : {Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1), Vec3d(1, 1, 1), Vec3d(0.2, 0, 0.7)}) {
    const Vec3f stored(to_acescg * srgb);
    const Vec3d back = to_srgb * Vec3d(stored);
    EXPECT_FALSE(is_outside_gamut(back)) << srgb.x << " " << srgb.y << " " << srgb.z;
  }
  EXPECT_TRUE(is_outside_gamut(to_srgb * Vec3d(0.6, 0.02, 0.02)));
  EXPECT_TRUE(is_outside_gamut(Vec3d(1.0, 0.5, -2e-5)));
  EXPECT_FALSE(is_outside_gamut(Vec3d(1.0, 0.5, -0.5e-5)));
  EXPECT_FALSE(is_outside_gamut(Vec3d(0.0)));  // black is inside every gamut
}

}  // namespace
}  // namespace prism::color
