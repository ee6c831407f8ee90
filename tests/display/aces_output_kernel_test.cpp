// The float/tabulated ACES block kernel (display/aces_output_kernel.h), which
// apply_display_pipeline uses, against the exact double-precision path (AcesOutputTransform
// per pixel, DisplaySettings::reference_path), and the Log2SpacedTable it is built on.
//
// Bound: 2e-5 of code value (all encodings' code is in [0, 1]; scRGB, linear light / 80
// nit, is compared relative to the pixel's brightest channel). Where it comes from:
//  - the tables (Log2SpacedTable, linear in x): ≤ |p(p − 1)|/8 · 2^-2k relative for a local
//    log–log slope p; 2^-18 for the tone curves, 2^-16 for the encodings, i.e. ≤ 1e-6;
//  - float arithmetic: ~20 roundings of 6e-8, ≤ 1e-6 relative;
//  - the display matrices: a saturated colour's small channel is the difference of large
//    AP1 values, which multiplies relative error by up to ~1000 in light, and a code value
//    moves by at most ~0.5 × the relative light error (d code / d ln L of the sRGB, BT.1886
//    and PQ curves), but only in channels ~1/1000 of the pixel's brightest.
// Measured: ≤ 5e-6 over the grid below (2^7 segments per octave for the tone curves gave
// 5e-5, and a chord through the tone curve's black corner instead of its square root gave
// 3e-4 after BT.1886: both fail). 2e-5 is a fiftieth of the OCIO oracle's 1e-3, so the
// kernel stays inside that oracle wherever the reference does with room to spare; 1/200
// of an 8-bit step and 1/50 of a 10-bit step; 4× the measured value so that another
// compiler's float contraction does not flake.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/log2_spaced_table.h"

namespace prism::display {
namespace {

constexpr double kMaxCodeError = 2e-5;

TEST(Log2SpacedTable, ExactAtSamplesLinearBetweenClampedOutside) {
  const Log2SpacedTable t([](double x) { return std::sqrt(x) + 0.25; }, -10, 4, 3);
  EXPECT_EQ(t.size(), std::size_t{14 * 8 + 1});
  for (double x : {std::ldexp(1.0, -10), 0.125, 1.0, 1.125, 1.25, 9.0, 16.0})
    EXPECT_FLOAT_EQ(t(static_cast<float>(x)), static_cast<float>(std::sqrt(x) + 0.25)) << x;
  // Halfway between two samples: the chord's midpoint.
  EXPECT_FLOAT_EQ(t(1.0625f), static_cast<float>(0.5 * (1.0 + std::sqrt(1.125)) + 0.25));
  // Below 2^-10: the chord from f(0) to f(2^-10); at and beyond the ends: clamped.
  EXPECT_FLOAT_EQ(t(std::ldexp(1.0f, -11)), static_cast<float>(0.25 + 0.5 * std::ldexp(1.0, -5)));
  EXPECT_FLOAT_EQ(t(0.0f), 0.25f);
  EXPECT_FLOAT_EQ(t(-3.0f), 0.25f);
  EXPECT_FLOAT_EQ(t(1e9f), 4.25f);
  EXPECT_FLOAT_EQ(t(std::numeric_limits<float>::infinity()), 4.25f);
  EXPECT_FLOAT_EQ(t(std::numeric_limits<float>::quiet_NaN()), 0.25f);  // never an index
}

TEST(Log2SpacedTable, InterpolationErrorWithinTheChordBound) {
  // x^p: the chord over [a, a(1 + 2^-k)] errs by ≤ |p(p − 1)|/8 · 2^-2k · x^p (to first order).
  for (double p : {0.4, 1.6, 3.0}) {
    const Log2SpacedTable t([p](double x) { return std::pow(x, p); }, -20, 10, 5);
    const double bound = std::fabs(p * (p - 1.0)) / 8.0 * std::ldexp(1.0, -10) * 1.05;
    double worst = 0.0;
    for (double x = std::ldexp(1.0, -20); x < 1000.0; x *= 1.0007) {
      const double f = std::pow(static_cast<double>(static_cast<float>(x)), p);
      worst = std::max(worst, std::fabs(t(static_cast<float>(x)) - f) / f);
    }
    EXPECT_LE(worst, bound) << p;
    EXPECT_GE(worst, bound / 4.0) << p;  // the bound is tight: the test can fail
  }
}

// ACES2065-1 values straight as film (the aces2065-1 film space has an identity matrix):
// every combination of a dense log ladder from 2^-40 to 2^40 with zero, negatives and
// float's extremes, so the red modifier, glow, clamps and every tone-curve segment are hit.
ImageRgbF dense_grid() {
  std::vector<float> levels{0.0f, -1e-4f, -0.05f, -30.0f, 3e38f, -3e38f, 1e20f};
  for (double e = -40.0; e <= 40.0; e += 1.5) levels.push_back(static_cast<float>(0.18 * std::exp2(e)));
  ImageRgbF img{static_cast<int>(levels.size() * levels.size()), static_cast<int>(levels.size()), {}};
  for (float b : levels)
    for (float g : levels)
      for (float r : levels) img.rgb.insert(img.rgb.end(), {r, g, b});
  return img;
}

struct Variant {
  std::string label;
  OdtId odt;
  std::optional<DisplayEncoding> encoding;
  bool stretch_black = true;
  bool remap = false;
};

struct Worst {
  double error = 0.0;
  std::string where;
};

Worst max_code_error(const ImageRgbF& film, const color::ColorSpace& space, DisplaySettings s, bool scrgb) {
  s.reference_path = true;
  const DisplayImage ref = apply_display_pipeline(film, space, s);
  s.reference_path = false;
  const DisplayImage fast = apply_display_pipeline(film, space, s);
  EXPECT_EQ(fast.code.size(), ref.code.size());
  Worst worst;
  for (std::size_t i = 0; i + 2 < ref.code.size(); i += 3) {
    const double scale = scrgb ? std::max({1e-3, std::fabs(double(ref.code[i])), std::fabs(double(ref.code[i + 1])),
                                           std::fabs(double(ref.code[i + 2]))})
                               : 1.0;
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(std::isfinite(fast.code[i + c]));
      const double e = std::fabs(double(fast.code[i + c]) - ref.code[i + c]) / scale;
      if (e > worst.error) {
        char where[200];
        std::snprintf(where, sizeof where, "film (%g, %g, %g) channel %d: reference %.7f, kernel %.7f", film.rgb[i],
                      film.rgb[i + 1], film.rgb[i + 2], c, ref.code[i + c], fast.code[i + c]);
        worst = {e, where};
      }
    }
  }
  return worst;
}

TEST(AcesOutputKernel, MatchesTheExactPathOnADenseGrid) {
  const std::vector<Variant> variants{
      {"none", OdtId::none, {}},
      {"srgb-100nit", OdtId::srgb_100nit, {}},
      {"rec709-100nit", OdtId::rec709_100nit, {}},
      {"p3d65-100nit", OdtId::p3d65_100nit, {}},
      {"rec2020-100nit", OdtId::rec2020_100nit, {}},
      {"rec2020-pq-1000nit", OdtId::rec2020_pq_1000nit, {}},
      {"rec2020-pq-1000nit Y_MIN", OdtId::rec2020_pq_1000nit, {}, false},
      {"rec2020-pq-2000nit", OdtId::rec2020_pq_2000nit, {}},
      {"rec2020-pq-4000nit", OdtId::rec2020_pq_4000nit, {}},
      {"p3d65-pq-1000nit", OdtId::p3d65_pq_1000nit, {}},
      {"p3d65-pq-1000nit remap", OdtId::p3d65_pq_1000nit, {}, true, true},
      {"srgb-100nit remap", OdtId::srgb_100nit, {}, true, true},
      {"rec2020-pq-1000nit scrgb", OdtId::rec2020_pq_1000nit, DisplayEncoding::scrgb},
      {"srgb-100nit pq", OdtId::srgb_100nit, DisplayEncoding::pq},
  };
  const ImageRgbF grid = dense_grid();
  const color::ColorSpace& ap0 = color::color_space("aces2065-1");
  for (const Variant& v : variants) {
    DisplaySettings s;
    s.odt = v.odt;
    s.encoding = v.encoding;
    s.stretch_black = v.stretch_black;
    if (v.remap) s.display_primaries = color::color_space("adobe-rgb");
    const bool scrgb = v.encoding == DisplayEncoding::scrgb;
    const Worst w = max_code_error(grid, ap0, s, scrgb);
    std::printf("[ kernel ] %-28s max |Δcode| %.2e over %zu pixels\n", v.label.c_str(), w.error, grid.rgb.size() / 3);
    EXPECT_LE(w.error, kMaxCodeError) << v.label << " at " << w.where;
  }
}

TEST(AcesOutputKernel, FoldsExposureLmtAndFilmMatrix) {
  // An sRGB film with exposure and the blue-light LMT: the folded matrices in float.
  const ImageRgbF grid = dense_grid();
  for (OdtId odt : {OdtId::srgb_100nit, OdtId::rec2020_pq_1000nit}) {
    DisplaySettings s;
    s.odt = odt;
    s.exposure_ev100 = -2.5;
    s.blue_correction = 0.6;
    const Worst w = max_code_error(grid, color::color_space("srgb"), s, false);
    EXPECT_LE(w.error, kMaxCodeError) << w.where;
  }
}

TEST(AcesOutputKernel, NonFiniteSamplesShowAsBlackChannels) {
  // As before the kernel: a NaN or ±Inf channel reads as 0, the others are kept.
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const ImageRgbF film{4, 1, {nan, 0.5f, 0.2f, 0.0f, 0.5f, 0.2f, inf, -inf, 0.3f, 0.0f, 0.0f, 0.3f}};
  for (OdtId odt : {OdtId::srgb_100nit, OdtId::rec2020_pq_1000nit, OdtId::none}) {
    DisplaySettings s;
    s.odt = odt;
    const DisplayImage out = apply_display_pipeline(film, color::color_space("srgb"), s);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(out.code[c], out.code[3 + c]);
      EXPECT_EQ(out.code[6 + c], out.code[9 + c]);
      EXPECT_EQ(out.nits[c], out.nits[3 + c]);
    }
  }
}

TEST(AcesOutputKernel, RenderScaleAndOverlayPathsMatchTheReference) {
  // The split paths (normalised code → upscale or overlay → display light) on a small image.
  ImageRgbF film{16, 8, std::vector<float>(16 * 8 * 3)};
  for (std::size_t i = 0; i < film.rgb.size(); ++i)
    film.rgb[i] = static_cast<float>(0.01 * std::exp2(0.11 * double(i)) * double(1 + i % 3));
  DisplaySettings s;
  s.odt = OdtId::rec2020_pq_1000nit;
  s.render_scale = 0.5;
  Worst w = max_code_error(film, color::color_space("srgb"), s, false);
  EXPECT_LE(w.error, kMaxCodeError) << w.where;

  s.render_scale = 1.0;
  EncodedImage ui{16, 8, 4, 8, std::vector<std::uint16_t>(16 * 8 * 4)};
  for (std::size_t i = 0; i < ui.samples.size(); ++i) ui.samples[i] = static_cast<std::uint16_t>((i * 37) % 256);
  s.overlay = make_ui_overlay(ui, 200.0, 5.0);
  w = max_code_error(film, color::color_space("srgb"), s, false);
  EXPECT_LE(w.error, kMaxCodeError) << w.where;
}

}  // namespace
}  // namespace prism::display
