// SampledSpectrum arithmetic and the pdf-weighted conversion to XYZ.
#include <gtest/gtest.h>

#include "prism/color/sampled_spectrum.h"
#include "prism/color/spectrum.h"

namespace prism::color {
namespace {

// The same arithmetic for every storage: vector lanes (N ≤ 4) and arrays (N > 4).
template <int N>
void expect_per_wavelength_arithmetic() {
  SampledSpectrum<N> a(2.0f), b;
  std::array<float, N> b_values{}, product{}, quotient{}, sum{}, difference{};
  for (int i = 0; i < N; ++i) {
    const float v = i % 3 == 2 ? 0.0f : static_cast<float>(i + 1);
    b[static_cast<std::size_t>(i)] = v;
    b_values[static_cast<std::size_t>(i)] = v;
    product[static_cast<std::size_t>(i)] = 2.0f * v;
    quotient[static_cast<std::size_t>(i)] = v != 0.0f ? 2.0f / v : 0.0f;  // x/0 → 0
    sum[static_cast<std::size_t>(i)] = 2.0f + v;
    difference[static_cast<std::size_t>(i)] = 2.0f - v;
  }
  EXPECT_EQ(b.array(), b_values);
  EXPECT_EQ((a * b).array(), product);
  EXPECT_EQ((a / b).array(), quotient);
  EXPECT_EQ((a + b).array(), sum);
  EXPECT_EQ((a - b).array(), difference);
  EXPECT_EQ((b * 3.0f).array(), (SampledSpectrum<N>(b_values) * SampledSpectrum<N>(3.0f)).array());
  float mean = 0.0f;
  for (float v : sum) mean += v;
  EXPECT_FLOAT_EQ((a + b).average(), mean / N);
  EXPECT_TRUE(SampledSpectrum<N>().is_black());
  EXPECT_FALSE(a.is_black());
}

TEST(SampledSpectrum, ArithmeticIsPerWavelength) {
  expect_per_wavelength_arithmetic<1>();
  expect_per_wavelength_arithmetic<3>();
  expect_per_wavelength_arithmetic<4>();
  expect_per_wavelength_arithmetic<8>();
}

// RGB (N = 3) lives in four lanes: the fourth must stay 0 through every operator, or
// is_black and average (which read N lanes) would still be right but a later division
// would not be, and the lanes are what the next spectrum is built from.
TEST(SampledSpectrum, LanesPastTheChannelsStayZero) {
  using Rgb = SampledSpectrum<3>;
  static_assert(Rgb::kVectorLanes && sizeof(Rgb) == 16);
  const Rgb a(2.0f), b(Rgb(std::array<float, 3>{1.0f, 0.0f, 4.0f}));
  for (const Rgb& r : {Rgb(1.0f), a + b, a - b, a * b, a / b, b / a, a * 5.0f, Rgb(1.0f) - b})
    EXPECT_EQ(r.values[3], 0.0f);
}

// A 4-wavelength spectrum is one 16-byte vector: it is passed and returned in one SSE
// register (the reason for the storage, sampled_spectrum.h).
static_assert(sizeof(SampledSpectrum<4>) == 16 && alignof(SampledSpectrum<4>) == 16);
static_assert(!SampledSpectrum<8>::kVectorLanes && sizeof(SampledSpectrum<8>) == 32);

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
