// Spectra given by scenes: names, black bodies, and the colours the rest of the scene sees.
#include <gtest/gtest.h>

#include "prism/color/illuminants.h"
#include "prism/scene/spectral_inputs.h"

namespace prism {
namespace {

TEST(SpectralInputs, NamesGiveTheCieTablesOverTheVisibleRange) {
  const auto d65 = named_emission_spectrum("D65");
  ASSERT_TRUE(d65);
  EXPECT_EQ(d65->wavelengths_nm().front(), 380.0);
  EXPECT_EQ(d65->wavelengths_nm().back(), 780.0);
  const color::DenseSpectrum& table = color::standard_illuminant(color::StandardIlluminant::d65);
  for (double nm : {380.0, 455.0, 560.0, 700.0, 780.0}) EXPECT_DOUBLE_EQ((*d65)(nm), table(nm)) << nm;
  const auto f11 = named_emission_spectrum("f11"), fl11 = named_emission_spectrum("FL11");
  ASSERT_TRUE(f11 && fl11);
  EXPECT_EQ(*f11, *fl11);
  EXPECT_DOUBLE_EQ((*f11)(545.0), color::fluorescent_illuminant(11)(545.0));
  for (const char* name : {"A", "D50", "E", "F1", "F12"}) EXPECT_TRUE(named_emission_spectrum(name)) << name;
  for (const char* name : {"", "F", "F0", "F13", "F011", "FL", "D66", "F2x", "blackbody"})
    EXPECT_FALSE(named_emission_spectrum(name)) << name;
}

TEST(SpectralInputs, BlackbodyAt2856KelvinIsIlluminantA) {
  // Illuminant A is a Planckian radiator of 2856 K (CIE 15:2004 §3.1); A's printed
  // chromaticity (0.44757, 0.40745) has 5 decimals, the 1 nm tabulation adds < 1e-5.
  const Vec3d xyz = color::spectrum_to_xyz(blackbody_emission_spectrum(2856.0));
  const color::Chromaticity c = color::XYZ_to_xy(xyz);
  EXPECT_NEAR(c.x, 0.44757, 2e-4);
  EXPECT_NEAR(c.y, 0.40745, 2e-4);
}

TEST(SpectralInputs, ColoursAreTheSpectraSeenByAD65BalancedCamera) {
  // D65 is sRGB's white: white up to the difference between the ASTM E308 white the table
  // integrates to and sRGB's printed xy (4th decimal, color_space.h).
  const Vec3f d65 = emission_spectrum_srgb(*named_emission_spectrum("D65"));
  EXPECT_NEAR(d65.x, 1.0f, 2e-3f);
  EXPECT_NEAR(d65.y, 1.0f, 2e-3f);
  EXPECT_NEAR(d65.z, 1.0f, 2e-3f);
  // Tungsten (A) is orange, a 10000 K black body blue.
  const Vec3f a = emission_spectrum_srgb(*named_emission_spectrum("A"));
  EXPECT_FLOAT_EQ(a.x, 1.0f);
  EXPECT_GT(a.y, a.z);
  EXPECT_LT(a.z, 0.5f);
  const Vec3f hot = emission_spectrum_srgb(blackbody_emission_spectrum(10000.0));
  EXPECT_FLOAT_EQ(hot.z, 1.0f);
  EXPECT_LT(hot.x, hot.y);
  // A flat reflectance of 0.4 is the grey 0.4: as a spectral render films it under a white
  // (flat) light, adapted E → D65 (the CMFs' ∫x̄ = ∫ȳ = ∫z̄ holds to 1e-4).
  const color::PiecewiseLinearSpectrum grey({400.0, 700.0}, {0.4, 0.4});
  const Vec3f g = reflectance_spectrum_srgb(grey);
  for (float v : {g.x, g.y, g.z}) EXPECT_NEAR(v, 0.4f, 1e-3f);
  // A reflectance that only returns red light is red, clipped into [0, 1].
  const color::PiecewiseLinearSpectrum red({380.0, 590.0, 610.0, 780.0}, {0.0, 0.0, 1.0, 1.0});
  const Vec3f r = reflectance_spectrum_srgb(red);
  EXPECT_GT(r.x, 0.5f);
  EXPECT_LE(r.x, 1.0f);
  EXPECT_LT(r.z, 0.05f);
}

}  // namespace
}  // namespace prism
