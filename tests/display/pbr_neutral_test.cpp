// Khronos PBR Neutral (display/pbr_neutral.h) against its specification
// (KhronosGroup/ToneMapping, PBR_Neutral/README.md): the guarantees it publishes (base
// colours in [0.08, 0.8] come out exactly F90 = 0.04 darker; no hue shift anywhere; C1
// continuity at the toe's and the shoulder's joins), hand-computed values, and its formula
// written here in the specification's own notation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "prism/color/color_space.h"
#include "prism/color/transfer_functions.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/pbr_neutral.h"

namespace prism::display {
namespace {

// The specification's equations, as its README writes them (F90 = 0.04, K_s = 0.8 − F90,
// K_d = 0.15): f = x − x²/(4F90) for x < 2F90 else F90; p_n = 1 − (1 − K_s)²/(p + 1 − 2K_s);
// g = 1 − 1/(K_d(p − p_n) + 1); c_out = (1 − g)·(p_n/p)·c + g·p_n.
Vec3d specification(const Vec3d& in) {
  const double F90 = 0.04, Ks = 0.8 - F90, Kd = 0.15;
  const double x = std::min({in[0], in[1], in[2]});
  const double f = x < 2 * F90 ? x - x * x / (4 * F90) : F90;
  const Vec3d c{in[0] - f, in[1] - f, in[2] - f};
  const double p = std::max({c[0], c[1], c[2]});
  if (p <= Ks) return c;
  const double pn = 1 - (1 - Ks) * (1 - Ks) / (p + 1 - 2 * Ks);
  const double g = 1 - 1 / (Kd * (p - pn) + 1);
  Vec3d out;
  for (int k = 0; k < 3; ++k) out[k] = (1 - g) * (pn / p) * c[k] + g * pn;
  return out;
}

// Double-precision arithmetic on the same operations in another order: 1e-14 is a few ulps.
constexpr double kFormulaTolerance = 1e-14;

TEST(PbrNeutral, BaseColoursInTheGuaranteedRangeComeOutF90Darker) {
  for (double r = 0.08; r < 0.8; r += 0.0425)
    for (double g = 0.08; g < 0.8; g += 0.0425)
      for (double b = 0.08; b < 0.8; b += 0.0425) {
        const Vec3d out = pbr_neutral({r, g, b});
        EXPECT_NEAR(out[0], r - 0.04, kFormulaTolerance);
        EXPECT_NEAR(out[1], g - 0.04, kFormulaTolerance);
        EXPECT_NEAR(out[2], b - 0.04, kFormulaTolerance);
      }
}

TEST(PbrNeutral, MatchesTheSpecificationsFormula) {
  const double ladder[] = {0.0, 0.001, 0.02, 0.0799, 0.08, 0.3, 0.7999, 0.8, 0.81, 1.0, 2.5, 10.0, 1000.0};
  for (double r : ladder)
    for (double g : ladder)
      for (double b : ladder) {
        const Vec3d out = pbr_neutral({r, g, b}), expected = specification({r, g, b});
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], expected[k], kFormulaTolerance) << r << " " << g << " " << b;
      }
}

// Worked by hand from the equations:
//  grey 0.04: f = 0.04 − 0.0016·6.25 = 0.03 → 0.01;
//  grey 0.18: f = F90 → 0.14;
//  grey 1: c = 0.96 ≥ K_s, p_n = 1 − 0.24²/(0.96 + 0.24 − 0.76) = 1 − 0.0576/0.44 → 0.869090909…
TEST(PbrNeutral, HandComputedGreys) {
  EXPECT_NEAR(pbr_neutral({0.04, 0.04, 0.04})[1], 0.01, 1e-15);
  EXPECT_NEAR(pbr_neutral({0.18, 0.18, 0.18})[1], 0.14, 1e-15);
  EXPECT_NEAR(pbr_neutral({1.0, 1.0, 1.0})[1], 1.0 - 0.0576 / 0.44, 1e-15);
}

// No hue shift: the output lies in the plane through the input and the white axis, so the
// triple product of input, output and (1, 1, 1) vanishes; and the peak only approaches 1.
TEST(PbrNeutral, NoHueShiftAndBoundedByWhite) {
  const double ladder[] = {0.003, 0.05, 0.2, 0.9, 3.0, 40.0, 1e4};
  for (double r : ladder)
    for (double g : ladder)
      for (double b : ladder) {
        const Vec3d in{r, g, b}, out = pbr_neutral(in);
        const double triple = in[0] * (out[1] - out[2]) - in[1] * (out[0] - out[2]) + in[2] * (out[0] - out[1]);
        EXPECT_NEAR(triple, 0.0, 1e-12 * std::max(1.0, r + g + b));
        EXPECT_LT(std::max({out[0], out[1], out[2]}), 1.0);
      }
}

// C1 at the joins: value and slope agree from both sides of x = 2·F90 (grey) and of the
// shoulder's start (peak = K_s, a saturated colour so the toe is off).
TEST(PbrNeutral, ContinuousWithContinuousSlopeAtTheJoins) {
  const double h = 1e-6;
  const auto grey = [](double v) { return pbr_neutral({v, v, v})[0]; };
  const double x0 = 0.08;
  EXPECT_NEAR(grey(x0 - h), grey(x0 + h), 3 * h);
  EXPECT_NEAR((grey(x0) - grey(x0 - h)) / h, (grey(x0 + h) - grey(x0)) / h, 1e-4);
  const auto red = [](double v) { return pbr_neutral({v, 0.1, 0.1})[0]; };
  const double r0 = kPbrNeutralStartCompression + 0.04;  // peak after the F90 offset = K_s
  EXPECT_NEAR(red(r0 - h), red(r0 + h), 3 * h);
  EXPECT_NEAR((red(r0) - red(r0 - h)) / h, (red(r0 + h) - red(r0)) / h, 1e-4);
}

// Through the pipeline: the srgb-100nit target encodes the display light with the sRGB curve
// (the specification's sRGB output), 1.0 = the display's white.
TEST(PbrNeutral, PipelineEncodesWithTheTargetsCurve) {
  ImageRgbF film{2, 1, {0.5f, 0.5f, 0.5f, 0.2f, 0.6f, 0.3f}};
  DisplaySettings s;
  s.rendering = Rendering::pbr_neutral;
  const DisplayImage shown = apply_display_pipeline(film, color::color_space("srgb"), s);
  const double expected[] = {0.46, 0.46, 0.46, 0.16, 0.56, 0.26};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(shown.nits[i], 100.0 * expected[i], 1e-4);  // float32 film and light
    EXPECT_NEAR(shown.code[i], color::srgb_encode(expected[i]), 1e-6);
  }
}

}  // namespace
}  // namespace prism::display
