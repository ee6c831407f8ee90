// End-to-end `prism tonemap` on the display-referred outputs: an .exr output is the display
// light of the target as scRGB (not the target's code values), the same light its PQ PNG
// encodes; scRGB refuses other display primaries; a file's values enter unscaled; and each
// output names its rendering in its metadata.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/transfer_functions.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "support/cli_test.h"

namespace prism {
namespace {

class TonemapDisplayCli : public test::CliTest {
 protected:
  // A 64×4 Rec.709 scene-linear EXR: greys from 1e-4 to 1e3 and saturated colours beside them.
  std::string write_input() {
    ImageRgbF image{64, 4, {}};
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 64; ++x) {
        const float v = static_cast<float>(std::pow(10.0, -4.0 + 7.0 * x / 63.0));
        const float rgb[4][3] = {{v, v, v}, {v, 0.02f * v, 0.0f}, {0.0f, v, 0.3f * v}, {0.1f * v, 0.2f * v, v}};
        for (int c = 0; c < 3; ++c) image.rgb.push_back(rgb[y][c]);
      }
    const color::ColorSpace& s = color::color_space("srgb");
    const auto f = [](double v) { return static_cast<float>(v); };
    write_exr(path("in.exr"), image,
              {f(s.red.x), f(s.red.y), f(s.green.x), f(s.green.y), f(s.blue.x), f(s.blue.y), f(s.white.x), f(s.white.y)});
    input_ = image;
    return path("in.exr");
  }
  ImageRgbF input_;
};

std::string png_text(const PngFile& png, const std::string& keyword) {
  for (const PngText& t : png.text)
    if (t.keyword == keyword) return t.text;
  return "";
}

TEST_F(TonemapDisplayCli, ExrIsScrgbDisplayLightEqualToThePqOutput) {
  const std::string in = write_input();
  ASSERT_EQ(run("tonemap " + in + " -o " + path("out.exr") + " --odt rec2020-pq-1000nit"), 0) << log();
  ASSERT_EQ(run("tonemap " + in + " -o " + path("out.png") + " --odt rec2020-pq-1000nit"), 0) << log();
  const ExrFile exr = read_exr(path("out.exr"));
  const PngFile png = read_png(path("out.png"));
  ASSERT_EQ(png.image.bit_depth, 16);
  ASSERT_EQ(exr.image.rgb.size(), png.image.samples.size());
  const Mat3 to_709 = color::conversion_matrix(color::color_space("rec2020"), color::color_space("srgb"));
  float max_scrgb = 0.0f;
  for (std::size_t p = 0; p < exr.image.rgb.size() / 3; ++p) {
    Vec3d nits, quantum;
    for (int c = 0; c < 3; ++c) {
      const double code = png.image.samples[3 * p + c] / 65535.0;
      nits[c] = color::pq_decode_nits(code);
      // Light within half a 16-bit PQ step of this code (the PNG's quantisation).
      quantum[c] = color::pq_decode_nits(std::min(1.0, code + 0.5 / 65535.0)) - nits[c];
    }
    const Vec3d light_709 = to_709 * nits;
    for (int r = 0; r < 3; ++r) {
      // Tolerance: the PQ step carried through the matrix, plus the half float's precision:
      // 2^-11 relative, and below half's normal range (6.1e-5) its subnormal step 2^-24,
      // which is 80·2^-24 = 4.8e-6 nit of scRGB light.
      double bound = 80.0 * std::ldexp(1.0, -24) + std::abs(light_709[r]) * std::ldexp(1.0, -11);
      for (int c = 0; c < 3; ++c) bound += std::abs(to_709.m[r][c]) * quantum[c];
      const double scrgb_nits = 80.0 * exr.image.rgb[3 * p + r];
      EXPECT_NEAR(scrgb_nits, light_709[r], bound) << "pixel " << p << " channel " << r;
      max_scrgb = std::max(max_scrgb, exr.image.rgb[3 * p + r]);
    }
  }
  // The brightest white reaches the ODT's 1000 nits: 12.5 in scRGB (not a PQ code below 1).
  EXPECT_GT(max_scrgb, 900.0f / 80.0f);
  EXPECT_EQ(exr.metadata.strings.at("prism:rendering"), "aces1");
}

TEST_F(TonemapDisplayCli, ScrgbRefusesOtherDisplayPrimaries) {
  const std::string in = write_input();
  EXPECT_EQ(run("tonemap " + in + " -o " + path("p.exr") + " --display-primaries adobe-rgb"), 2) << log();
  EXPECT_NE(log().find("scRGB"), std::string::npos) << log();
  EXPECT_FALSE(std::filesystem::exists(path("p.exr")));
}

// Without an exposure option the file's values enter unscaled: the `none` target shows the
// input's Rec.709 light with 1.0 = 80 nits, so its scRGB EXR holds the input itself.
TEST_F(TonemapDisplayCli, ValuesEnterUnscaled) {
  const std::string in = write_input();
  ASSERT_EQ(run("tonemap " + in + " -o " + path("none.exr") + " --odt none"), 0) << log();
  const ExrFile out = read_exr(path("none.exr"));
  ASSERT_EQ(out.image.rgb.size(), input_.rgb.size());
  for (std::size_t i = 0; i < input_.rgb.size(); ++i) {
    const std::size_t p = i / 3;
    const float peak = std::max({input_.rgb[3 * p], input_.rgb[3 * p + 1], input_.rgb[3 * p + 2]});
    // Half floats: 2^-11 relative, and a subnormal step of 6e-8 below 6.1e-5; the float32
    // Rec.709 → ACES → Rec.709 matrices on the way: a few ulps (2^-24 each) of the pixel's
    // largest channel, bounded by 2^-20 of it.
    const double bound = std::abs(input_.rgb[i]) * std::ldexp(1.0, -11) + 6e-8 + peak * std::ldexp(1.0, -20);
    EXPECT_NEAR(out.image.rgb[i], input_.rgb[i], bound) << i;
  }
}

TEST_F(TonemapDisplayCli, OutputsNameTheirRendering) {
  const std::string in = write_input();
  ASSERT_EQ(run("tonemap " + in + " -o " + path("agx.png") + " --rendering agx --odt p3d65-100nit"), 0) << log();
  const PngFile png = read_png(path("agx.png"));
  EXPECT_EQ(png_text(png, "prism:rendering"), "agx");
  EXPECT_EQ(png_text(png, "prism:displayTarget"), "p3d65-100nit");
  EXPECT_NE(log().find("rendering agx, target p3d65-100nit"), std::string::npos) << log();
  ASSERT_EQ(run("tonemap " + in + " -o " + path("pbr.exr") + " --rendering pbr-neutral"), 0) << log();
  EXPECT_EQ(read_exr(path("pbr.exr")).metadata.strings.at("prism:rendering"), "pbr-neutral");
}

}  // namespace
}  // namespace prism
