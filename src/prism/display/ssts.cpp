#include "prism/display/ssts.h"

#include <algorithm>
#include <cmath>

#include "prism/display/aces_common.h"
#include "prism/display/log_segmented_spline.h"

namespace prism::display {
namespace {

// Stop and luminance anchors of ACESlib.SSTS.ctl (published Academy data).
constexpr double kMinStopSdr = -6.5, kMaxStopSdr = 6.5;
constexpr double kMinStopRrt = -15.0, kMaxStopRrt = 18.0;
constexpr double kMinLumSdr = 0.02, kMaxLumSdr = 48.0;
constexpr double kMinLumRrt = 0.0001, kMaxLumRrt = 10000.0;

// interpolate1D of a two-entry table: linear between the entries, clamped outside.
double interpolate2(double x0, double y0, double x1, double y1, double x) {
  if (x <= x0) return y0;
  if (x >= x1) return y1;
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

double aces_min(double min_nits) {
  return 0.18 * std::pow(2.0, interpolate2(std::log10(kMinLumRrt), kMinStopRrt, std::log10(kMinLumSdr),
                                           kMinStopSdr, std::log10(min_nits)));
}
double aces_max(double max_nits) {
  return 0.18 * std::pow(2.0, interpolate2(std::log10(kMaxLumSdr), kMaxStopSdr, std::log10(kMaxLumRrt),
                                           kMaxStopRrt, std::log10(max_nits)));
}

// The value at log10(p.x) ± half a knot on the tangent line through point p.
double tangent_at(const TsPoint& p, double offset) {
  return p.slope * (std::log10(p.x) + offset) + (std::log10(p.y) - p.slope * std::log10(p.x));
}

double shift_stops(double x, double exp_shift) { return std::pow(2.0, std::log2(x) - exp_shift); }

}  // namespace

TsParams make_ts_params(double y_min_nits, double y_max_nits, double exp_shift) {
  TsPoint lo{aces_min(y_min_nits), y_min_nits, 0.0};
  TsPoint mid{0.18, 4.8, 1.55};
  TsPoint hi{aces_max(y_max_nits), y_max_nits, 0.0};
  TsParams p;
  // init_coefsLow: two values straddling each end on its tangent; the middle one sets the
  // sharpness of the bend, interpolated between the RRT's and the SDR curve's.
  const double inc_low = (std::log10(mid.x) - std::log10(lo.x)) / 3.0;
  p.coefs_low[0] = tangent_at(lo, -0.5 * inc_low);
  p.coefs_low[1] = tangent_at(lo, 0.5 * inc_low);
  p.coefs_low[3] = tangent_at(mid, -0.5 * inc_low);
  p.coefs_low[4] = tangent_at(mid, 0.5 * inc_low);
  const double pct_low = interpolate2(kMinStopRrt, 0.18, kMinStopSdr, 0.35, std::log2(lo.x / 0.18));
  p.coefs_low[2] = std::log10(lo.y) + pct_low * (std::log10(mid.y) - std::log10(lo.y));
  p.coefs_low[5] = p.coefs_low[4];
  // init_coefsHigh, likewise between mid and max.
  const double inc_high = (std::log10(hi.x) - std::log10(mid.x)) / 3.0;
  p.coefs_high[0] = tangent_at(mid, -0.5 * inc_high);
  p.coefs_high[1] = tangent_at(mid, 0.5 * inc_high);
  p.coefs_high[3] = tangent_at(hi, -0.5 * inc_high);
  p.coefs_high[4] = tangent_at(hi, 0.5 * inc_high);
  const double pct_high = interpolate2(kMaxStopSdr, 0.89, kMaxStopRrt, 0.90, std::log2(hi.x / 0.18));
  p.coefs_high[2] = std::log10(mid.y) + pct_high * (std::log10(hi.y) - std::log10(mid.y));
  p.coefs_high[5] = p.coefs_high[4];
  // The coefficients are computed on the unshifted axis; only the x anchors move.
  lo.x = shift_stops(lo.x, exp_shift);
  mid.x = shift_stops(mid.x, exp_shift);
  hi.x = shift_stops(hi.x, exp_shift);
  p.min = lo;
  p.mid = mid;
  p.max = hi;
  return p;
}

TsParams make_output_ts_params(double y_min_nits, double y_mid_nits, double y_max_nits) {
  const TsParams unshifted = make_ts_params(y_min_nits, y_max_nits);
  const double exp_shift = std::log2(inv_ssts(y_mid_nits, unshifted)) - std::log2(0.18);
  return make_ts_params(y_min_nits, y_max_nits, exp_shift);
}

double ssts(double x, const TsParams& p) {
  const LogSegmentedSpline s{p.min.x, p.min.y, p.min.slope, p.mid.x, p.max.x, p.max.y, p.max.slope,
                             p.coefs_low, p.coefs_high, 4};
  return std::pow(10.0, evaluate_log10(s, std::log10(std::max(x, kHalfMin))));
}

double inv_ssts(double y_nits, const TsParams& p) {
  constexpr int kKnots = 4;
  const double logy = std::log10(std::max(y_nits, 1e-10));
  // Solves a·t² + b·t + (c − logy) = 0 on the span whose knot luminances bracket logy;
  // the knot values are the midpoints of consecutive control values.
  auto solve = [logy](const std::array<double, 6>& cf, double log_start, double knot_inc) {
    int j = 2;
    for (int i = 0; i < 2; ++i)
      if (logy <= 0.5 * (cf[i + 1] + cf[i + 2])) { j = i; break; }
    double a, b, c;
    bspline_span_polynomial(cf[j], cf[j + 1], cf[j + 2], a, b, c);
    c -= logy;
    const double d = std::sqrt(b * b - 4.0 * a * c);
    const double t = (2.0 * c) / (-d - b);
    return log_start + (t + j) * knot_inc;
  };
  const double lmin = std::log10(p.min.x), lmid = std::log10(p.mid.x), lmax = std::log10(p.max.x);
  double logx;
  if (logy <= std::log10(p.min.y)) logx = lmin;
  else if (logy <= std::log10(p.mid.y)) logx = solve(p.coefs_low, lmin, (lmid - lmin) / (kKnots - 1));
  else if (logy < std::log10(p.max.y)) logx = solve(p.coefs_high, lmid, (lmax - lmid) / (kKnots - 1));
  else logx = lmax;
  return std::pow(10.0, logx);
}

}  // namespace prism::display
