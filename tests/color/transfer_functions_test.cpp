// Transfer functions: published values, exact float round trips, monotonicity.
#include "prism/color/transfer_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "prism/core/error.h"

namespace prism::color {
namespace {

using Fn = std::function<double(double)>;

// Round trip "exact to float precision": a float x, widened, encoded and decoded in double,
// must round back to the same float. Our double error (~1e-15 relative) is far below
// float's half-ulp (3e-8), so any failure is a real inversion error, not noise.
void expect_float_round_trip(const Fn& forward, const Fn& backward, double lo, double hi, bool log_spaced,
                             int n = 200001) {
  int failures = 0;
  for (int i = 0; i < n; ++i) {
    const double t = double(i) / (n - 1);
    const float x = float(log_spaced ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t);
    const float back = float(backward(forward(double(x))));
    if (back != x && ++failures <= 5) ADD_FAILURE() << "x = " << x << " came back as " << back;
  }
  EXPECT_EQ(failures, 0);
}

// Increasing on a dense grid (exact comparison: any decrease is a bug). `strict` false
// allows flat steps, for grids finer than a deliberately flat piece.
void expect_increasing(const Fn& f, double lo, double hi, int n = 200001, bool strict = true) {
  double previous = f(lo);
  for (int i = 1; i < n; ++i) {
    const double x = lo + (hi - lo) * double(i) / (n - 1);
    const double y = f(x);
    if (strict)
      ASSERT_GT(y, previous) << "at x = " << x;
    else
      ASSERT_GE(y, previous) << "at x = " << x;
    previous = y;
  }
}

TEST(ColorTransferSrgb, PublishedValues) {
  // IEC 61966-2-1 §5.2/§5.3: both printed breaks fall on the linear segment.
  EXPECT_DOUBLE_EQ(srgb_decode(0.04045), 0.04045 / 12.92);
  EXPECT_DOUBLE_EQ(srgb_encode(0.0031308), 12.92 * 0.0031308);
  EXPECT_DOUBLE_EQ(srgb_encode(1.0), 1.0);
  EXPECT_DOUBLE_EQ(srgb_decode(1.0), 1.0);
  // Code 0.5 is linear 0.214041 (a commonly quoted value, 6 decimals: half-unit tolerance).
  EXPECT_NEAR(srgb_decode(0.5), 0.214041, 0.5e-6);
  // Extended by odd symmetry (scRGB-nl / sYCC convention).
  EXPECT_DOUBLE_EQ(srgb_encode(-0.25), -srgb_encode(0.25));
  EXPECT_DOUBLE_EQ(srgb_decode(-0.5), -srgb_decode(0.5));
}

TEST(ColorTransferSrgb, RoundTripsAndIsMonotonic) {
  expect_float_round_trip(srgb_encode, srgb_decode, -1.0, 1.0, false);
  expect_float_round_trip(srgb_decode, srgb_encode, -1.0, 1.0, false);
  expect_float_round_trip(srgb_encode, srgb_decode, 1e-8, 1.0, true);
  expect_increasing(srgb_encode, -1.0, 1.0);
  expect_increasing(srgb_decode, -1.0, 1.0);
  // Across the segment join at a 1e-11 step: the ~2e-9 wide gap that decode never
  // produces is flat by design (see transfer_functions.cpp), so only non-decreasing.
  expect_increasing(srgb_encode, 0.04045 / 12.92 - 1e-8, 0.04045 / 12.92 + 1e-8, 2001, false);
}

TEST(ColorTransferBt1886, PublishedFormAndDisplayForm) {
  EXPECT_DOUBLE_EQ(bt1886_decode(0.5), std::pow(0.5, 2.4));
  EXPECT_DOUBLE_EQ(bt1886_decode(0.0), 0.0);
  EXPECT_DOUBLE_EQ(bt1886_decode(-0.1), 0.0);  // clamped
  // BT.1886 Annex 1: V = 0 gives the black luminance, V = 1 the white luminance.
  EXPECT_NEAR(bt1886_decode_nits(0.0, 100.0, 0.1), 0.1, 1e-12);
  EXPECT_NEAR(bt1886_decode_nits(1.0, 100.0, 0.1), 100.0, 1e-12);
  EXPECT_NEAR(bt1886_decode_nits(0.5, 100.0, 0.0), 100.0 * std::pow(0.5, 2.4), 1e-12);
  EXPECT_THROW(bt1886_decode_nits(0.5, 100.0, 200.0), UsageError);
  EXPECT_THROW(bt1886_encode_nits(50.0, 100.0, -1.0), UsageError);
}

TEST(ColorTransferBt1886, RoundTripsAndIsMonotonic) {
  expect_float_round_trip(bt1886_encode, bt1886_decode, 1e-8, 1.0, true);
  expect_float_round_trip(bt1886_decode, bt1886_encode, 0.0, 1.0, false);
  const Fn enc = [](double l) { return bt1886_encode_nits(l, 250.0, 0.05); };
  const Fn dec = [](double v) { return bt1886_decode_nits(v, 250.0, 0.05); };
  expect_float_round_trip(enc, dec, 0.05, 250.0, true);
  expect_increasing(enc, 0.0, 250.0);
  expect_increasing(bt1886_decode, 0.0, 1.0);
}

TEST(ColorTransferPq, PublishedValues) {
  // Issue 3 / common ST 2084 tables, 6 decimals: half-unit tolerance.
  EXPECT_NEAR(pq_encode_nits(100.0), 0.508078, 0.5e-6);
  EXPECT_NEAR(pq_encode_nits(1000.0), 0.751827, 0.5e-6);
  EXPECT_NEAR(pq_encode_nits(10000.0), 1.0, 1e-15);
  EXPECT_NEAR(pq_decode_nits(1.0), 10000.0, 1e-9);
  EXPECT_EQ(pq_decode_nits(0.0), 0.0);
  EXPECT_EQ(pq_decode_nits(-0.5), 0.0);  // clamped to the standard's domain
  EXPECT_NEAR(pq_decode_nits(pq_encode_nits(203.0)), 203.0, 1e-9);
}

TEST(ColorTransferPq, RoundTripsAndIsMonotonic) {
  expect_float_round_trip(pq_encode_nits, pq_decode_nits, 1e-4, 10000.0, true);
  expect_float_round_trip(pq_decode_nits, pq_encode_nits, 0.01, 1.0, false);
  expect_increasing(pq_encode_nits, 0.0, 10000.0);
  expect_increasing(pq_decode_nits, pq_encode_nits(0.0), 1.0);
}

TEST(ColorTransferHlg, PublishedValues) {
  // BT.2100-2 Table 5 prints b and c to 8 decimals; ours are derived from a.
  const double c_from_code = 0.55991073;
  EXPECT_NEAR(hlg_encode(1.0 / 12.0), 0.5, 1e-15);
  EXPECT_NEAR(hlg_decode(0.5), 1.0 / 12.0, 1e-15);
  // E = 1 maps to E' = 1 up to the rounding of a to 8 decimals (~5e-9).
  EXPECT_NEAR(hlg_encode(1.0), 1.0, 1e-8);
  // Where 12E − b = 1 the log term vanishes and E' = c.
  EXPECT_NEAR(hlg_encode((1.0 + 0.28466892) / 12.0), c_from_code, 0.5e-8);
  EXPECT_EQ(hlg_encode(-1.0), 0.0);
}

TEST(ColorTransferHlg, RoundTripsAndIsMonotonic) {
  expect_float_round_trip(hlg_encode, hlg_decode, 1e-8, 1.0, true);
  expect_float_round_trip(hlg_decode, hlg_encode, 1e-4, 1.0, false);
  expect_increasing(hlg_encode, 0.0, 1.0);
  expect_increasing(hlg_decode, 0.0, 1.0);
}

TEST(ColorTransferScrgb, EightyNitsIsOne) {
  EXPECT_EQ(scrgb_from_nits(80.0), 1.0);
  EXPECT_EQ(scrgb_from_nits(10000.0), 125.0);
  EXPECT_EQ(scrgb_from_nits(-8.0), -0.1);
  EXPECT_EQ(scrgb_to_nits(scrgb_from_nits(123.5)), 123.5);
}

TEST(ColorTransferAcescc, PublishedValues) {
  // S-2014-003: 18% grey encodes to 0.4135884 (7 decimals), 0 to (9.72 − 16) / 17.52.
  EXPECT_NEAR(acescc_encode(0.18), 0.4135884, 0.5e-7);
  EXPECT_NEAR(acescc_encode(0.0), (9.72 - 16.0) / 17.52, 1e-15);
  EXPECT_NEAR(acescc_encode(-1.0), (9.72 - 16.0) / 17.52, 1e-15);
  EXPECT_NEAR(acescc_encode(std::exp2(-15.0)), (9.72 - 15.0) / 17.52, 1e-15);  // toe join
  EXPECT_EQ(acescc_decode(2.0), 65504.0);                                      // half-float ceiling
}

TEST(ColorTransferAcescc, RoundTripsAndIsMonotonic) {
  expect_float_round_trip(acescc_encode, acescc_decode, 1e-6, 65000.0, true);
  expect_float_round_trip(acescc_decode, acescc_encode, acescc_encode(0.0) + 1e-3, 1.45, false);
  expect_increasing(acescc_encode, 0.0, 65504.0);
  expect_increasing(acescc_decode, acescc_encode(0.0), acescc_encode(65000.0));
}

TEST(ColorTransferAcescct, PublishedConstants) {
  // S-2016-001 §4.4 prints A = 10.5402377416545 and B = 0.0729055341958355 (15 and 16
  // significant digits); ours are derived from the break, so they agree to that precision.
  EXPECT_NEAR(acescct_encode(0.0), 0.0729055341958355, 1e-15);
  EXPECT_NEAR((acescct_encode(0.0078125) - acescct_encode(0.0)) / 0.0078125, 10.5402377416545, 1e-12);
  EXPECT_NEAR(acescct_encode(0.0078125), 0.155251141552511, 1e-15);  // Y_BRK
  EXPECT_NEAR(acescct_encode(0.18), 0.4135884, 0.5e-7);
  EXPECT_EQ(acescct_decode(2.0), 65504.0);
}

TEST(ColorTransferAcescct, RoundTripsAndIsMonotonic) {
  expect_float_round_trip(acescct_encode, acescct_decode, 1e-6, 65000.0, true);
  expect_float_round_trip(acescct_encode, acescct_decode, -0.005, 0.0078125, false);
  expect_float_round_trip(acescct_decode, acescct_encode, 0.0, 1.45, false);
  expect_increasing(acescct_encode, -0.01, 65504.0);
  expect_increasing(acescct_decode, 0.0, acescct_encode(65000.0));
}

TEST(ColorTransferTransferFunction, NamesAndGenericDispatch) {
  for (const std::string& name : transfer_function_names())
    EXPECT_EQ(transfer_function_name(parse_transfer_function(name)), name);
  EXPECT_EQ(parse_transfer_function("PQ"), TransferFunction::pq);
  EXPECT_EQ(parse_transfer_function("st2084"), TransferFunction::pq);
  EXPECT_EQ(parse_transfer_function("sRGB"), TransferFunction::srgb);
  EXPECT_THROW(parse_transfer_function("gamma22"), UsageError);
  EXPECT_DOUBLE_EQ(transfer_encode(TransferFunction::pq, 0.01), pq_encode_nits(100.0));
  // PQ's exponents (m2 ≈ 78.8, 1/m1 ≈ 6.3) amplify double rounding ~100-fold: 1e-12
  // relative is still four orders below float precision.
  EXPECT_NEAR(transfer_decode(TransferFunction::pq, pq_encode_nits(100.0)), 0.01, 1e-14);
  EXPECT_EQ(transfer_encode(TransferFunction::scrgb, -0.5), -0.5);
  for (const std::string& name : transfer_function_names()) {
    const TransferFunction tf = parse_transfer_function(name);
    EXPECT_NEAR(transfer_decode(tf, transfer_encode(tf, 0.18)), 0.18, 1e-12) << name;
  }
}

}  // namespace
}  // namespace prism::color
