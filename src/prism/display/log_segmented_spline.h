#pragma once
// The shape every ACES 1.x tone curve shares (aces-dev lib/ACESlib.Tonescales.ctl,
// SegmentedSplineParams_c5/_c9; lib/ACESlib.SSTS.ctl): in log10–log10 space a straight line
// below the low point, a uniform quadratic B-spline from the low to the middle point and
// another from the middle to the high point, and a straight line above the high point.
#include <cmath>
#include <span>

namespace prism::display {

// The quadratic a·t² + b·t + c of one B-spline span from three consecutive control values,
// the CTL's basis M = {{½, −1, ½}, {−1, 1, ½}, {½, 0, 0}} (mult_f3_f33(cf, M)).
inline void bspline_span_polynomial(double c0, double c1, double c2, double& a, double& b, double& c) {
  a = 0.5 * c0 - c1 + 0.5 * c2;
  b = c1 - c0;
  c = 0.5 * (c0 + c1);
}

// That span at t ∈ [0, 1).
inline double bspline_span(double c0, double c1, double c2, double t) {
  double a, b, c;
  bspline_span_polynomial(c0, c1, c2, a, b, c);
  return (a * t + b) * t + c;
}

struct LogSegmentedSpline {
  double min_x, min_y, slope_low;   // the low point (linear values) and the log–log slope below it
  double mid_x;                     // where the two splines meet
  double max_x, max_y, slope_high;  // the high point and the slope above it
  std::span<const double> coefs_low, coefs_high;  // log10 control values of each half
  int knots;  // knots per half: N − 2 for the C5/C9 tables of N values, 4 for the SSTS
};

// log10 of the curve at log10 x.
inline double evaluate_log10(const LogSegmentedSpline& s, double logx) {
  const double lmin = std::log10(s.min_x), lmid = std::log10(s.mid_x), lmax = std::log10(s.max_x);
  if (logx <= lmin) return logx * s.slope_low + (std::log10(s.min_y) - s.slope_low * lmin);
  if (logx >= lmax) return logx * s.slope_high + (std::log10(s.max_y) - s.slope_high * lmax);
  const bool low = logx < lmid;
  const std::span<const double> cf = low ? s.coefs_low : s.coefs_high;
  const double knot = (s.knots - 1) * (low ? (logx - lmin) / (lmid - lmin) : (logx - lmid) / (lmax - lmid));
  const int j = static_cast<int>(knot);
  return bspline_span(cf[j], cf[j + 1], cf[j + 2], knot - j);
}

}  // namespace prism::display
