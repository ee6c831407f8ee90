// SampledSpectrum arithmetic and the pdf-weighted conversion to XYZ.
#include <gtest/gtest.h>

#include "prism/color/sampled_spectrum.h"
#include "prism/color/spectrum.h"

namespace prism::color {
namespace {

TEST(SampledSpectrum, ArithmeticIsPerWavelength) {
  SampledSpectrum<4> a(2.0f), b;
  b.values = {1.0f, 2.0f, 0.0f, 4.0f};
  EXPECT_EQ((a * b).values, (std::array<float, 4>{2, 4, 0, 8}));
  EXPECT_EQ((a / b).values, (std::array<float, 4>{2, 1, 0, 0.5f}));  // x/0 → 0
  EXPECT_FLOAT_EQ((a + b).average(), 3.75f);
  EXPECT_TRUE(SampledSpectrum<8>().is_black());
}

TEST(SampledSpectrum, XyzWeightsEachWavelengthByItsPdf) {
  SampledWavelengths<3> w;
  w.wavelength_nm = {450.0f, 555.0f, 600.0f};
  w.pdf = {0.01f, 0.02f, 0.0f};  // a zero pdf contributes nothing
  const SampledSpectrum<3> s = sample_spectrum(ConstantSpectrum{2.0}, w);
  const Vec3d xyz = to_xyz(s, w);
  const Vec3d expected = (cie1931_xyz_bar(450.0) * (2.0 / 0.01) + cie1931_xyz_bar(555.0) * (2.0 / 0.02)) / 3.0;
  EXPECT_NEAR(xyz.x, expected.x, 1e-4 * expected.x);
  EXPECT_NEAR(xyz.y, expected.y, 1e-4 * expected.y);
  EXPECT_NEAR(xyz.z, expected.z, 1e-4 * expected.z);
  EXPECT_NEAR(luminance_nits(s, w), 683.0 * xyz.y, 1e-9 * xyz.y);
}

}  // namespace
}  // namespace prism::color
