#pragma once
// The ACES 1.1+ single-stage tone scale (aces-dev lib/ACESlib.SSTS.ctl): one segmented
// quadratic B-spline from scene values straight to display luminance in nits, with its
// ends set by the display's black (Y_MIN) and peak (Y_MAX) luminance and its mid-grey
// placed, through an exposure shift, so that ACES 0.18 maps to Y_MID.
#include <array>

namespace prism::display {

struct TsPoint {
  double x, y, slope;  // scene value, luminance (nits), log–log slope
};

struct TsParams {
  TsPoint min, mid, max;
  std::array<double, 6> coefs_low, coefs_high;  // log10 luminance control values
};

// init_TsParams: the curve for display range [y_min_nits, y_max_nits] with the scene axis
// shifted by exp_shift stops.
TsParams make_ts_params(double y_min_nits, double y_max_nits, double exp_shift = 0.0);

// The Output Transform's curve: the shift that sends 0.18 to y_mid_nits (CTL: expShift =
// log2(inv_ssts(Y_MID)) − log2(0.18) on the unshifted curve).
TsParams make_output_ts_params(double y_min_nits, double y_mid_nits, double y_max_nits);

// Forward curve: scene value → luminance (nits).
double ssts(double x, const TsParams& p);
// Its inverse (inv_ssts): luminance (nits) → scene value, clamped to [min.x, max.x].
double inv_ssts(double y_nits, const TsParams& p);

}  // namespace prism::display
