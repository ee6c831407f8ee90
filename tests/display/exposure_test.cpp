// Exact-value tests of the exposure stage (Lagarde & de Rousiers 2014, §5.1) and of the
// tone-scale anchor points the Academy publishes (ACES 0.18 → 4.8 nit OCES, SSTS 0.18 → Y_MID).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "prism/core/error.h"
#include "prism/display/dither.h"
#include "prism/display/exposure.h"
#include "prism/display/segmented_spline.h"
#include "prism/display/ssts.h"

namespace prism::display {
namespace {

TEST(Exposure, Ev100FromCameraIsExact) {
  // f/1, 1 s, ISO 100 → log2(1) = 0; f/16, 1/100 s, ISO 100 (sunny 16) → log2(25600).
  EXPECT_EQ(ev100_from_camera(1.0, 1.0, 100.0), 0.0);
  EXPECT_DOUBLE_EQ(ev100_from_camera(16.0, 0.01, 100.0), std::log2(25600.0));
  // Doubling ISO lowers EV100 by exactly one stop; f/2 at 1/4 s, ISO 400 → log2(4) = 2.
  EXPECT_EQ(ev100_from_camera(2.0, 0.25, 400.0), 2.0);
  EXPECT_THROW(ev100_from_camera(0.0, 1.0, 100.0), UsageError);
  EXPECT_THROW(ev100_from_camera(2.0, -1.0, 100.0), UsageError);
  EXPECT_THROW(ev100_from_camera(2.0, 1.0, std::nan("")), UsageError);
}

TEST(Exposure, MaxLuminanceAndScaleAreExact) {
  EXPECT_EQ(max_luminance_nits_from_ev100(0.0), 1.2);
  EXPECT_EQ(max_luminance_nits_from_ev100(10.0), 1.2 * 1024.0);
  EXPECT_EQ(max_luminance_nits_from_ev100(-3.0), 0.15);
  EXPECT_EQ(exposure_scale_from_ev100(3.0), 1.0 / 9.6);
  EXPECT_THROW(max_luminance_nits_from_ev100(std::nan("")), UsageError);
  EXPECT_THROW(exposure_scale_from_ev100(INFINITY), UsageError);
}

TEST(Exposure, AutoExposureMapsLogAverageToKey) {
  // Two pixels of luminance 1 and 100 (δ = 0): log average √100 = 10.
  const std::vector<float> rgb{1, 1, 1, 100, 100, 100};
  const Vec3d weights{0.2126, 0.7152, 0.0722};
  const double l_avg = log_average_luminance(rgb, weights, 0.0);
  EXPECT_NEAR(l_avg, 10.0, 1e-12);
  const double ev = auto_exposure_ev100(l_avg, 0.18);
  EXPECT_NEAR(ev, std::log2(10.0 / (1.2 * 0.18)), 1e-12);
  EXPECT_NEAR(exposure_scale_from_ev100(ev) * l_avg, 0.18, 1e-12);
}

TEST(ToneScales, PublishedAnchorPoints) {
  // RRT_PARAMS: mid point (0.18, 4.8), min (0.18·2^-15, 1e-4), max (0.18·2^18, 1e4).
  EXPECT_NEAR(segmented_spline_c5_fwd(0.18), 4.8, 4.8 * 1e-9);
  EXPECT_NEAR(segmented_spline_c5_fwd(0.18 * std::pow(2.0, 18)), 10000.0, 1e-6);
  EXPECT_NEAR(segmented_spline_c5_fwd(1e-9), 0.0001, 1e-12);
  // ODT_48nits: OCES 4.8 at mid grey → 4.8 nit; the cinema black and white ends.
  EXPECT_NEAR(segmented_spline_c9_fwd(segmented_spline_c5_fwd(0.18)), 4.8, 1e-6);
  EXPECT_NEAR(segmented_spline_c9_fwd(1e-9), 0.02, 1e-9);
  // SSTS of the HDR Output Transforms: 0.18 → Y_MID = 15 nit; ends at Y_MIN and Y_MAX.
  for (double y_max : {1000.0, 2000.0, 4000.0}) {
    const TsParams p = make_output_ts_params(0.0001, 15.0, y_max);
    EXPECT_NEAR(ssts(0.18, p), 15.0, 15.0 * 1e-9) << y_max;
    EXPECT_NEAR(ssts(1e6, p), y_max, y_max * 1e-9);
    EXPECT_NEAR(ssts(0.0, p), 0.0001, 1e-12);
    EXPECT_NEAR(inv_ssts(ssts(2.0, p), p), 2.0, 2.0 * 1e-9);  // inverse round trip
  }
}

TEST(Dither, TriangularOneLsbDeterministicAndUnbiased) {
  double sum = 0.0, sum_sq = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double d = triangular_dither_lsb(7, static_cast<std::uint64_t>(i));
    ASSERT_GT(d, -1.0);
    ASSERT_LT(d, 1.0);
    EXPECT_EQ(d, triangular_dither_lsb(7, static_cast<std::uint64_t>(i)));
    sum += d;
    sum_sq += d * d;
  }
  // TPDF on (−1, 1): mean 0, variance 1/6. Standard error of the mean √(1/6/n) ≈ 9e-4, so
  // 5e-3 is > 5σ; the variance estimate's standard error is ≈ 4e-4.
  EXPECT_NEAR(sum / n, 0.0, 5e-3);
  EXPECT_NEAR(sum_sq / n, 1.0 / 6.0, 3e-3);
  EXPECT_NE(triangular_dither_lsb(7, 1), triangular_dither_lsb(8, 1));
  EXPECT_EQ(quantise_code(0.5, 8), 128);
  EXPECT_EQ(quantise_code(1.2, 8), 255);
  EXPECT_EQ(quantise_code(-0.1, 10), 0);
  EXPECT_EQ(quantise_code(1.0, 10), 1023);
  EXPECT_EQ(quantise_code(std::nan(""), 16), 0);
}

}  // namespace
}  // namespace prism::display
