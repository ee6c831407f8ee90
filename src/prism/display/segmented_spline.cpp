#include "prism/display/segmented_spline.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "prism/display/aces_common.h"
#include "prism/display/log_segmented_spline.h"

namespace prism::display {
namespace {

template <std::size_t N>
struct SplineParams {
  std::array<double, N> coefs_low, coefs_high;  // log10 luminance control values
  double min_x, min_y, mid_x, mid_y, max_x, max_y;
  double slope_low, slope_high;  // log–log slopes of the linear extensions
};

// The shared evaluation of SegmentedSplineParams_c5/_c9: N − 2 knots per half.
template <std::size_t N>
double evaluate(const SplineParams<N>& p, double logx) {
  const LogSegmentedSpline s{p.min_x, p.min_y, p.slope_low, p.mid_x, p.max_x, p.max_y, p.slope_high,
                             p.coefs_low, p.coefs_high, static_cast<int>(N) - 2};
  return std::pow(10.0, evaluate_log10(s, logx));
}

// RRT_PARAMS of ACESlib.Tonescales.ctl (published Academy data).
const SplineParams<6>& rrt_params() {
  static const SplineParams<6> p{
      {-4.0000000000, -4.0000000000, -3.1573765773, -0.4852499958, 1.8477324706, 1.8477324706},
      {-0.7185482425, 2.0810307172, 3.6681241237, 4.0000000000, 4.0000000000, 4.0000000000},
      0.18 * std::pow(2.0, -15.0), 0.0001,
      0.18, 4.8,
      0.18 * std::pow(2.0, 18.0), 10000.0,
      0.0, 0.0};
  return p;
}

// ODT_48nits of ACESlib.Tonescales.ctl (published Academy data); its x breakpoints are
// the RRT curve at 0.18·2^−6.5, 0.18 and 0.18·2^6.5.
const SplineParams<10>& odt_48nit_params() {
  static const SplineParams<10> p{
      {-1.6989700043, -1.6989700043, -1.4779000000, -1.2291000000, -0.8648000000, -0.4480000000,
       0.0051800000, 0.4511080334, 0.9113744414, 0.9113744414},
      {0.5154386965, 0.8470437783, 1.1358000000, 1.3802000000, 1.5197000000, 1.5985000000, 1.6467000000,
       1.6746091357, 1.6878733390, 1.6878733390},
      segmented_spline_c5_fwd(0.18 * std::pow(2.0, -6.5)), 0.02,
      segmented_spline_c5_fwd(0.18), 4.8,
      segmented_spline_c5_fwd(0.18 * std::pow(2.0, 6.5)), 48.0,
      0.0, 0.04};
  return p;
}

}  // namespace

double segmented_spline_c5_fwd(double x) {
  // Non-positive input is floored at HALF_MIN before the log, as in the CTL.
  return evaluate(rrt_params(), std::log10(std::max(x, kHalfMin)));
}

double segmented_spline_c9_fwd(double x) {
  // The C9 curve floors non-positive input at 1e-4 (the CTL's OCESMIN) instead.
  return evaluate(odt_48nit_params(), std::log10(x <= 0.0 ? 1e-4 : x));
}

}  // namespace prism::display
