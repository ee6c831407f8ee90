// The emission rule: adapt to E, fit, scale to the requested luminance; a working-space
// white light renders neutral, and the E-neutral film convention is what makes it so.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/illuminants.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/spectrum.h"

namespace prism::color {
namespace {

// The luminance the film shows (Y after the film's E → working-white adaptation) is the
// requested one; for a grey that is 683 ∫ L ȳ dλ itself.
TEST(EmissionSpectrum, FilmedLuminanceIsExactlyTheRequestedNits) {
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const ColorSpace& space = color_space(name);
    const Mat3 e_to_working = adaptation_matrix(xy_to_XYZ(kWhiteE), white_XYZ(space), Cat::bradford);
    for (const Vec3d rgb : {Vec3d(1, 1, 1), Vec3d(1, 0.2, 0.05), Vec3d(0.1, 0.2, 3.0)}) {
      const EmissionSpectrum s = emission_spectrum(rgb, space, 250.0);
      // K is defined by this very integral, so only rounding remains.
      EXPECT_NEAR(683.0 * (e_to_working * spectrum_to_xyz(s)).y, 250.0, 1e-9) << name;
    }
    EXPECT_NEAR(683.0 * spectrum_to_xyz(emission_spectrum({1, 1, 1}, space, 250.0)).y, 250.0, 1e-9) << name;
  }
  const ColorSpace& srgb = color_space("srgb");
  EXPECT_EQ(emission_spectrum({0, 0, 0}, srgb, 100.0).scale, 0.0);
  EXPECT_THROW(emission_spectrum({1, 1, 1}, srgb, -1.0), UsageError);
}

// A light of known RGB given its own luminance films as that RGB: the pbrt-v4 Cornell box's
// `rgb L [17 12 4]` came out 0.6 % dark when the E-relative Y was normalised instead.
// Bound 1e-4 relative: the fit converges to ~1e-6 in XYZ, and the film's integral is the
// same trapezoid rule; spectral renders add only Monte Carlo noise to this (the render
// test in tests/render/emitter_film_test.cpp).
TEST(EmissionSpectrum, LightOfKnownRgbFilmsAsThatRgb) {
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const ColorSpace& space = color_space(name);
    for (const Vec3d rgb : {Vec3d(17, 12, 4), Vec3d(1, 0.5, 0.2), Vec3d(0.2, 0.4, 1.0), Vec3d(0.3, 1.0, 0.3)}) {
      const double nits = (space.rgb_to_xyz * rgb).y;
      const Vec3d out = spectral_xyz_to_rgb_matrix(space) * spectrum_to_xyz(emission_spectrum(rgb, space, nits)) * 683.0;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c] / rgb[c], 1.0, 1e-4) << name << " channel " << c;
    }
  }
}

TEST(EmissionSpectrum, WorkingWhiteLightRendersNeutral) {
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const ColorSpace& space = color_space(name);
    const Vec3d xyz = spectrum_to_xyz(emission_spectrum({1, 1, 1}, space, 100.0));
    const Vec3d rgb = spectral_xyz_to_rgb_matrix(space) * xyz;
    // Neutral: equal channels, i.e. the working white's chromaticity. The fit converges to
    // 1e-6 ΔE, so the channels agree to ~1e-6 relative; bound 1e-5.
    EXPECT_NEAR(rgb.x / rgb.y, 1.0, 1e-5) << name;
    EXPECT_NEAR(rgb.z / rgb.y, 1.0, 1e-5) << name;
    const Chromaticity c = XYZ_to_xy(space.rgb_to_xyz * rgb);
    EXPECT_NEAR(c.x, space.white.x, 1e-5) << name;
    EXPECT_NEAR(c.y, space.white.y, 1e-5) << name;
  }
}

TEST(EmissionSpectrum, WithoutAdaptationD65WhiteTurnsReddish) {
  // The adapted white light is the flat (E) spectrum. Read as working RGB without the
  // E → D65 adaptation, equal energy is reddish in sRGB: E's xy (1/3, 1/3) lies on the
  // warm side of D65 (0.3127, 0.3290). That is the seed renderer's "reddish image".
  const ColorSpace& srgb = color_space("srgb");
  const Vec3d xyz = spectrum_to_xyz(emission_spectrum({1, 1, 1}, srgb, 100.0));
  const Vec3d rgb = srgb.xyz_to_rgb * xyz;
  std::printf("sRGB white light without adaptation: rgb ratio r/g %.4f, b/g %.4f\n", rgb.x / rgb.y, rgb.z / rgb.y);
  EXPECT_GT(rgb.x / rgb.y, 1.2);   // measured 1.27
  EXPECT_LT(rgb.z / rgb.y, 0.97);  // measured 0.958
}

TEST(EmissionSpectrum, ColouredLightsKeepTheirChromaticity) {
  const ColorSpace& srgb = color_space("srgb");
  for (const Vec3d rgb : {Vec3d(1, 0.5, 0.2), Vec3d(0.2, 0.4, 1.0), Vec3d(0.3, 1.0, 0.3)}) {
    const Vec3d out = spectral_xyz_to_rgb_matrix(srgb) * spectrum_to_xyz(emission_spectrum(rgb, srgb, 10.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c] / out.y, rgb[c] / rgb.y, 1e-4) << c;
  }
}

}  // namespace
}  // namespace prism::color
