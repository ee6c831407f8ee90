#pragma once
// ACES 2.0 gamut compression (ACES 2.0 "Output Transform technical details", "Gamut
// compression"; aces-core lib/Lib.Academy.OutputTransform.ctl gamut_compress_fwd/_inv).
// In the J–M plane of one hue the limiting gamut is approximated by two power curves
// meeting at its cusp (lower hull exponent 1.14 + 0.07 log10(peak/100), upper hull exponent
// per hue from a table), smoothed together. Each colour is moved along a line aimed at a
// focus point on the J axis (between the cusp's J and mid grey's J, at a distance growing
// with the peak) towards that boundary: M beyond 75 % of the boundary (or beyond the ratio
// of the limiting to the reach boundary, if larger) is compressed with a Reinhard curve
// that maps the reach (AP1) boundary onto the limiting one.
#include "prism/core/vec.h"

namespace prism::display {

// Parameters shared by every hue.
struct Aces2GamutGeometry {
  double limit_j_max;           // J of the display peak
  double mid_j;                 // J of the tonescale's mid grey
  double focus_distance;        // 1.35 (1 + 1.75 log10(peak/100))
  double lower_hull_gamma_inv;  // 1 / (1.14 + 0.07 log10(peak/100))
};

// Parameters of one hue, from the cusp and gamma tables.
struct Aces2HueShape {
  double cusp_j, cusp_m;   // cusp M already widened by the cusp smoothing (1 + 0.27 · 0.12)
  double gamma_top_inv;
  double focus_j;
  double analytical_threshold;
};

// Focus J and analytical threshold of a cusp (the rest of Aces2HueShape).
Aces2HueShape make_hue_shape(double cusp_j, double cusp_m, double gamma_top_inv, const Aces2GamutGeometry& g);

// The pieces the table builder needs as well as the transform.
double aces2_focus_gain(double J, double analytical_threshold, const Aces2GamutGeometry& g);
double aces2_solve_j_intersect(double J, double M, double focus_j, double max_j, double slope_gain);
double aces2_compression_vector_slope(double intersect_j, double focus_j, double limit_j_max, double slope_gain);
double aces2_gamut_boundary_m(const Aces2HueShape& s, double limit_j_max, double gamma_top_inv,
                              double lower_hull_gamma_inv, double j_intersect_source, double slope,
                              double j_intersect_cusp);

// Forward and inverse compression of (J, M) at one hue; reach_max_m is the reach gamut's
// M at limit_j_max for that hue. Returns (J, M).
Vec2<double> aces2_gamut_compress_forward(double J, double M, double reach_max_m, const Aces2HueShape& s,
                                          const Aces2GamutGeometry& g);
Vec2<double> aces2_gamut_compress_inverse(double J, double M, double reach_max_m, const Aces2HueShape& s,
                                          const Aces2GamutGeometry& g);

}  // namespace prism::display
