#pragma once
// Shared pieces of the ACES 1.x output transforms (Academy aces-dev v1.3, lib/
// ACESlib.Utilities.ctl, ACESlib.Transform_Common.ctl, ACESlib.RRT_Common.ctl): the
// AP0/AP1 matrices, the AP1 luminance weights, the D60→D65 Bradford adaptation and the
// small helpers (saturation, hue, yc, shapers) the RRT and ODTs share.
//
// No matrix is pasted in: every one is derived by prism::color from the primaries of
// SMPTE ST 2065-1 (AP0) and S-2014-004 (AP1), which is how the CTL builds them too.
#include "prism/core/mat3.h"
#include "prism/core/vec.h"

namespace prism::display {

// Constants of the CTL (ACESlib.Utilities.ctl), kept as float-valued doubles.
inline constexpr double kHalfMin = 5.96046448e-08;  // smallest positive half (subnormal)
inline constexpr double kHalfMax = 65504.0;         // largest finite half

struct AcesMatrices {
  Mat3 ap0_to_ap1, ap1_to_ap0;
  Mat3 ap1_to_xyz, xyz_to_ap1;  // relative to the ACES white, Y of RGB white = 1
  Vec3d ap1_luminance;          // second row of ap1_to_xyz (AP1_RGB2Y)
  Mat3 d60_to_d65;              // Bradford, ACES white → D65 (calculate_cat_matrix)
};
const AcesMatrices& aces_matrices();

// The CTL's calc_sat_adjust_matrix, written for column vectors: out = s·in + (1 − s)·Y(in).
Mat3 saturation_matrix(double saturation, const Vec3d& luminance_weights);

// (max − min) / max with the CTL's floors (TINY = 1e-10, max floor 1e-2).
double rgb_saturation(const Vec3d& rgb);
// Luminance proxy yc with the chroma "radius" weight 1.75.
double rgb_yc(const Vec3d& rgb);
// Hue angle in degrees [0, 360); NaN for achromatic input (CTL returns FLT_NAN).
double rgb_hue_degrees(const Vec3d& rgb);
// Smooth step from 0 to 1 over x in [−2, 2] (sigmoid_shaper).
double sigmoid_shaper(double x);
// Uniform cubic B-spline bump of total width `width`, peak 1 at x = 0 (cubic_basis_shaper).
double cubic_basis_shaper(double x, double width);
// Hue difference wrapped into [−180, 180].
double center_hue(double hue, double center);

}  // namespace prism::display
