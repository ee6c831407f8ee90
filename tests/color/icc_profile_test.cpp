// ICC display profiles (color/icc_profile.h) checked by an independent colour-management
// implementation, Little CMS 2 (Debian's liblcms2): it must accept our bytes as a v4.4
// display RGB profile, and its transform of code values to PCS XYZ must agree with
//   (a) our own math: decode the curve, RGB→XYZ of the space, Bradford to D50, and
//   (b) a profile Little CMS builds itself from the same primaries, white and curve
//       (cmsCreateRGBProfile, which derives and adapts the colorants with its own code).
#include "prism/color/icc_profile.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <lcms2.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/transfer_functions.h"

namespace prism::color {
namespace {

struct ProfileCloser {
  void operator()(void* p) const { cmsCloseProfile(p); }
};
struct TransformDeleter {
  void operator()(void* t) const { cmsDeleteTransform(t); }
};
using Profile = std::unique_ptr<void, ProfileCloser>;
using Transform = std::unique_ptr<void, TransformDeleter>;

Profile open(const std::vector<std::uint8_t>& bytes) {
  return Profile(cmsOpenProfileFromMem(bytes.data(), static_cast<cmsUInt32Number>(bytes.size())));
}

// Code values → PCS XYZ (D50-relative, Y of white = 1), relative colorimetric, in doubles.
std::vector<Vec3d> to_pcs(void* profile, const std::vector<Vec3d>& rgb) {
  Profile xyz(cmsCreateXYZProfile());
  Transform t(cmsCreateTransform(profile, TYPE_RGB_DBL, xyz.get(), TYPE_XYZ_DBL, INTENT_RELATIVE_COLORIMETRIC,
                                 cmsFLAGS_NOOPTIMIZE | cmsFLAGS_NOCACHE));
  EXPECT_TRUE(t);
  std::vector<Vec3d> out(rgb.size());
  if (!t) return out;
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    const double in[3] = {rgb[i].x, rgb[i].y, rgb[i].z};
    double o[3];
    cmsDoTransform(t.get(), in, o, 1);
    out[i] = {o[0], o[1], o[2]};
  }
  return out;
}

double decode(IccToneCurve curve, double v) {
  switch (curve) {
    case IccToneCurve::srgb: return srgb_decode(v);
    case IccToneCurve::gamma_2_4: return std::pow(v, 2.4);
    case IccToneCurve::gamma_2_2: return std::pow(v, 563.0 / 256.0);
    case IccToneCurve::gamma_2_6: return std::pow(v, 2.6);
  }
  return 0.0;
}

cmsToneCurve* lcms_curve(IccToneCurve curve) {
  if (curve == IccToneCurve::srgb) {
    const double p[5] = {2.4, 1.0 / 1.055, 0.055 / 1.055, 1.0 / 12.92, 0.04045};
    return cmsBuildParametricToneCurve(nullptr, 4, p);  // lcms type 4 = ICC type 3
  }
  return cmsBuildGamma(nullptr, curve == IccToneCurve::gamma_2_4   ? 2.4
                                : curve == IccToneCurve::gamma_2_6 ? 2.6
                                                                   : 563.0 / 256.0);
}

Profile lcms_reference(const ColorSpace& s, IccToneCurve curve) {
  const cmsCIExyY white{s.white.x, s.white.y, 1.0};
  const cmsCIExyYTRIPLE primaries{{s.red.x, s.red.y, 1.0}, {s.green.x, s.green.y, 1.0}, {s.blue.x, s.blue.y, 1.0}};
  cmsToneCurve* c = lcms_curve(curve);
  cmsToneCurve* curves[3] = {c, c, c};
  Profile p(cmsCreateRGBProfile(&white, &primaries, curves));
  cmsFreeToneCurve(c);
  return p;
}

std::vector<Vec3d> probe_codes() {
  std::vector<Vec3d> v;
  for (double r : {0.0, 0.02, 0.3, 0.75, 1.0})
    for (double g : {0.0, 0.5, 1.0})
      for (double b : {0.0, 0.1, 0.9}) v.push_back({r, g, b});
  return v;
}

struct Case {
  const char* space;
  IccToneCurve curve;
};

class IccProfile : public ::testing::TestWithParam<Case> {};

TEST_P(IccProfile, LittleCmsReadsItAsAV4DisplayProfile) {
  const Case c = GetParam();
  const std::vector<std::uint8_t> bytes = make_icc_display_profile(color_space(c.space), c.curve, "test");
  ASSERT_EQ(bytes.size() % 4, 0u);
  const Profile p = open(bytes);
  ASSERT_TRUE(p);
  EXPECT_EQ(cmsGetEncodedICCversion(p.get()), 0x04400000u);
  EXPECT_EQ(cmsGetDeviceClass(p.get()), cmsSigDisplayClass);
  EXPECT_EQ(cmsGetColorSpace(p.get()), cmsSigRgbData);
  EXPECT_EQ(cmsGetPCS(p.get()), cmsSigXYZData);
  EXPECT_TRUE(cmsIsMatrixShaper(p.get()));
  char text[64] = {};
  cmsGetProfileInfoASCII(p.get(), cmsInfoDescription, "en", "US", text, sizeof text);
  EXPECT_STREQ(text, "test");
  // Byte-identical from call to call (fixed date, no profile ID).
  EXPECT_EQ(bytes, make_icc_display_profile(color_space(c.space), c.curve, "test"));
}

// Tolerance: the profile stores colorants, chad and curve parameters as s15Fixed16
// (steps of 1.5e-5); an error of half a step in each of three colorants moves XYZ by at
// most ~2.3e-5, and Little CMS evaluates in double. 1e-4 leaves room for that and for
// the curve's parameter rounding near black, and is 50× below an 8-bit code step.
constexpr double kPcsTolerance = 1e-4;

TEST_P(IccProfile, LittleCmsTransformMatchesOurColourMath) {
  const Case c = GetParam();
  const ColorSpace& space = color_space(c.space);
  const Profile p = open(make_icc_display_profile(space, c.curve, "test"));
  ASSERT_TRUE(p);
  const Mat3 to_pcs_matrix =
      adaptation_matrix(white_XYZ(space), icc_pcs_illuminant_XYZ(), Cat::bradford) * space.rgb_to_xyz;
  const std::vector<Vec3d> codes = probe_codes();
  const std::vector<Vec3d> lcms = to_pcs(p.get(), codes);
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const Vec3d linear(decode(c.curve, codes[i].x), decode(c.curve, codes[i].y), decode(c.curve, codes[i].z));
    const Vec3d ours = to_pcs_matrix * linear;
    EXPECT_NEAR(lcms[i].x, ours.x, kPcsTolerance) << c.space << " code " << i;
    EXPECT_NEAR(lcms[i].y, ours.y, kPcsTolerance) << c.space << " code " << i;
    EXPECT_NEAR(lcms[i].z, ours.z, kPcsTolerance) << c.space << " code " << i;
  }
}

TEST_P(IccProfile, AgreesWithTheProfileLittleCmsBuildsFromTheSamePrimaries) {
  const Case c = GetParam();
  const ColorSpace& space = color_space(c.space);
  const Profile ours = open(make_icc_display_profile(space, c.curve, "test"));
  const Profile theirs = lcms_reference(space, c.curve);
  ASSERT_TRUE(ours);
  ASSERT_TRUE(theirs);
  const std::vector<Vec3d> codes = probe_codes();
  const std::vector<Vec3d> a = to_pcs(ours.get(), codes), b = to_pcs(theirs.get(), codes);
  for (std::size_t i = 0; i < codes.size(); ++i) {
    EXPECT_NEAR(a[i].x, b[i].x, kPcsTolerance) << c.space << " code " << i;
    EXPECT_NEAR(a[i].y, b[i].y, kPcsTolerance) << c.space << " code " << i;
    EXPECT_NEAR(a[i].z, b[i].z, kPcsTolerance) << c.space << " code " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Spaces, IccProfile,
                         ::testing::Values(Case{"srgb", IccToneCurve::srgb}, Case{"display-p3", IccToneCurve::srgb},
                                           Case{"adobe-rgb", IccToneCurve::gamma_2_2},
                                           Case{"rec2020", IccToneCurve::gamma_2_4},
                                           Case{"dci-p3", IccToneCurve::gamma_2_4},
                                           Case{"display-p3", IccToneCurve::gamma_2_6}));

// The white of every space lands on the PCS illuminant (D50) through its colorants: the
// sum of the colorant columns is chad · white = D50 (ICC.1 §D.3).
TEST(IccColorants, SumToThePcsIlluminant) {
  for (const char* name : {"srgb", "display-p3", "adobe-rgb", "rec2020", "dci-p3", "acescg"}) {
    const Mat3 m = icc_colorant_matrix(color_space(name));
    const Vec3d sum = m * Vec3d(1.0);
    const Vec3d d50 = icc_pcs_illuminant_XYZ();
    EXPECT_NEAR(sum.x, d50.x, 1e-9) << name;
    EXPECT_NEAR(sum.y, d50.y, 1e-9) << name;
    EXPECT_NEAR(sum.z, d50.z, 1e-9) << name;
  }
  // Published D50-adapted sRGB colorants (Lindbloom, sRGB with Bradford to D50, first
  // row 0.4360747 0.3850649 0.1430804); Lindbloom's D50 white is 0.96422, 1, 0.82521,
  // the ICC PCS illuminant 0.9642, 1, 0.8249: the difference (3e-4 in Z) bounds the
  // tolerance.
  const Mat3 srgb = icc_colorant_matrix(color_space("srgb"));
  EXPECT_NEAR(srgb.m[0][0], 0.4360747, 2e-4);
  EXPECT_NEAR(srgb.m[0][1], 0.3850649, 2e-4);
  EXPECT_NEAR(srgb.m[0][2], 0.1430804, 2e-4);
}

}  // namespace
}  // namespace prism::color
