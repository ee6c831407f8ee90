// Gamut remap to the user's display primaries (display/display_primaries.h) and the
// spectral-locus check behind `--display-primaries`.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/display_primaries.h"
#include "prism/display/spectral_locus.h"

namespace prism::display {
namespace {

TEST(DisplayGamutRemap, SpectralLocus) {
  EXPECT_TRUE(inside_spectral_locus({0.3127, 0.3290}));  // D65
  // Rec.2020's primaries are monochromatic (630, 532, 467 nm): on the locus, accepted.
  for (color::Chromaticity c : {color::Chromaticity{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}})
    EXPECT_TRUE(inside_spectral_locus(c)) << c.x << "," << c.y;
  // AP0's primaries are imaginary: outside.
  EXPECT_FALSE(inside_spectral_locus({0.7347, 0.2653 - 0.01}));
  EXPECT_FALSE(inside_spectral_locus({0.0, 1.0}));
  EXPECT_FALSE(inside_spectral_locus({0.0001, -0.0770}));
  EXPECT_FALSE(inside_spectral_locus({0.5, 0.1}));  // below the line of purples
}

TEST(DisplayGamutRemap, ParsesNamesAndNumbers) {
  EXPECT_EQ(parse_display_primaries("adobe-rgb").green.x, color::color_space("adobe-rgb").green.x);
  EXPECT_NEAR(parse_display_primaries("display-p3").red.x, 0.680, 1e-12);
  const color::ColorSpace s = parse_display_primaries("0.64,0.33,0.21,0.71,0.15,0.06,0.3127,0.329");
  EXPECT_NEAR(s.green.y, 0.71, 1e-12);
  EXPECT_NO_THROW(parse_display_primaries("xy:0.64,0.33,0.3,0.6,0.15,0.06,0.3127,0.329"));
}

TEST(DisplayGamutRemap, RejectsInvalidPrimaries) {
  // Collinear primaries.
  EXPECT_THROW(parse_display_primaries("0.2,0.2,0.3,0.3,0.4,0.4,0.3127,0.329"), UsageError);
  // A red beyond the spectral locus (a valid triangle, but not a real display).
  EXPECT_THROW(parse_display_primaries("0.75,0.30,0.21,0.71,0.15,0.06,0.3127,0.329"), UsageError);
  // AP0, imaginary primaries.
  EXPECT_THROW(parse_display_primaries("aces2065-1"), UsageError);
  EXPECT_THROW(parse_display_primaries("0.64,0.33,0.21"), UsageError);
  EXPECT_THROW(parse_display_primaries("not-a-space"), UsageError);
}

ImageRgbF gamut_test_film() {
  ImageRgbF film{16, 1, {}};
  for (int x = 0; x < 16; ++x) {
    const double v = 0.01 * std::pow(2.0, x * 0.7);
    const double tint[4][3] = {{1, 1, 1}, {1, 0.1, 0.05}, {0.05, 1, 0.1}, {0.1, 0.2, 1}};
    for (int c = 0; c < 3; ++c) film.rgb.push_back(static_cast<float>(v * tint[x % 4][c]));
  }
  return film;
}

TEST(DisplayGamutRemap, OwnPrimariesAreIdentity) {
  DisplaySettings s;
  s.odt = OdtId::rec2020_pq_1000nit;
  const DisplayImage a = apply_display_pipeline(gamut_test_film(), color::color_space("srgb"), s);
  s.display_primaries = parse_display_primaries("rec2020");
  const DisplayImage b = apply_display_pipeline(gamut_test_film(), color::color_space("srgb"), s);
  for (std::size_t i = 0; i < a.code.size(); ++i) EXPECT_NEAR(a.code[i], b.code[i], 1e-6);
}

TEST(DisplayGamutRemap, RemapShowsTheSameLightInsideTheTargetGamut) {
  // SDR P3 ODT → an Adobe RGB display: in-gamut colours keep their XYZ (both D65 whites,
  // so Bradford is the identity); the output is tagged with the target primaries.
  DisplaySettings s;
  s.odt = OdtId::p3d65_100nit;
  const DisplayImage p3 = apply_display_pipeline(gamut_test_film(), color::color_space("srgb"), s);
  s.display_primaries = parse_display_primaries("adobe-rgb");
  const DisplayImage adobe = apply_display_pipeline(gamut_test_film(), color::color_space("srgb"), s);
  EXPECT_EQ(adobe.primaries, "adobe-rgb");
  const Mat3 p3_xyz = color::color_space("display-p3").rgb_to_xyz, adobe_xyz = color::color_space("adobe-rgb").rgb_to_xyz;
  int compared = 0;
  for (std::size_t i = 0; i < p3.nits.size() / 3; ++i) {
    const Vec3d a{adobe.nits[3 * i], adobe.nits[3 * i + 1], adobe.nits[3 * i + 2]};
    if (std::min({a.x, a.y, a.z}) <= 0.0 || std::max({a.x, a.y, a.z}) >= 100.0) continue;  // clipped
    const Vec3d xa = adobe_xyz * a, xp = p3_xyz * Vec3d{p3.nits[3 * i], p3.nits[3 * i + 1], p3.nits[3 * i + 2]};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(xa[k], xp[k], 1e-4 * (1 + xp.y));  // float storage
    ++compared;
  }
  EXPECT_GT(compared, 4);
  // Saturated green lies outside Adobe RGB's gamut in some channel: clipped to [0, 100].
  for (float v : adobe.nits) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 100.0f);
  }
}

TEST(DisplayGamutRemap, AdaptsToTheDisplayWhite) {
  // A D50 display: the ODT's D65 white shows as the display's own white (R = G = B).
  DisplaySettings s;
  s.odt = OdtId::srgb_100nit;
  s.display_primaries = parse_display_primaries("0.64,0.33,0.30,0.60,0.15,0.06,0.3457,0.3585");
  ImageRgbF grey{1, 1, {0.18f, 0.18f, 0.18f}};
  const DisplayImage out = apply_display_pipeline(grey, color::color_space("srgb"), s);
  EXPECT_NEAR(out.nits[0], out.nits[1], 1e-3);
  EXPECT_NEAR(out.nits[2], out.nits[1], 1e-3);
}

}  // namespace
}  // namespace prism::display
