#include "prism/display/aces2_gamut_compression.h"

#include <algorithm>
#include <cmath>

#include "prism/display/hellwig_cam.h"

namespace prism::display {
namespace {

constexpr double kSmoothCusps = 0.12;
constexpr double kCuspMidBlend = 1.3;
constexpr double kFocusGainBlend = 0.3;
constexpr double kCompressionThreshold = 0.75;

double lerp(double a, double b, double t) { return a + t * (b - a); }

// Smooth minimum (cubic polynomial) with a smoothing width relative to `reference`.
double smooth_min(double a, double b, double reference) {
  const double s = kSmoothCusps * reference;
  const double h = std::max(s - std::abs(a - b), 0.0) / s;
  return std::min(a, b) - h * h * h * s / 6.0;
}

// M where the line J = slope·M + j_axis meets the power curve J = j_max (M/m_max)^(1/γ),
// approximated by shifting the line's axis intersection through the curve's exponent
// about `reference` and intersecting with the straight line from the origin to the cusp.
double line_boundary_intersection_m(double j_axis, double slope, double gamma_inv, double j_max, double m_max,
                                    double reference) {
  const double shifted = reference * std::pow(j_axis / reference, gamma_inv);
  return shifted * m_max / (j_max - slope * m_max);
}

// Reinhard compression of [threshold, ∞) onto [threshold, limit); `invert` undoes it.
double remap_m(double M, double gamut_boundary_m, double reach_boundary_m, bool invert) {
  const double proportion = std::max(gamut_boundary_m / reach_boundary_m, kCompressionThreshold);
  const double threshold = proportion * gamut_boundary_m;
  if (M <= threshold || proportion >= 1.0) return M;
  const double m_offset = M - threshold;
  const double gamut_offset = gamut_boundary_m - threshold;
  const double reach_offset = reach_boundary_m - threshold;
  const double scale = reach_offset / ((reach_offset / gamut_offset) - 1.0);
  const double nd = m_offset / scale;
  if (!invert) return threshold + scale * nd / (1.0 + nd);
  return threshold + (nd >= 1.0 ? scale : scale * -(nd / (nd - 1.0)));
}

// One compression step with the focus gain evaluated at jx (J itself going forward; an
// estimate of the uncompressed J in the inverse).
Vec2<double> compress(double J, double M, double jx, double reach_max_m, const Aces2HueShape& s,
                      const Aces2GamutGeometry& g, bool invert) {
  const double slope_gain = aces2_focus_gain(jx, s.analytical_threshold, g);
  const double j_intersect_source = aces2_solve_j_intersect(J, M, s.focus_j, g.limit_j_max, slope_gain);
  const double slope = aces2_compression_vector_slope(j_intersect_source, s.focus_j, g.limit_j_max, slope_gain);
  const double j_intersect_cusp = aces2_solve_j_intersect(s.cusp_j, s.cusp_m, s.focus_j, g.limit_j_max, slope_gain);
  const double boundary_m = aces2_gamut_boundary_m(s, g.limit_j_max, s.gamma_top_inv, g.lower_hull_gamma_inv,
                                                   j_intersect_source, slope, j_intersect_cusp);
  if (boundary_m <= 0.0) return {J, 0.0};
  const double reach_boundary_m = line_boundary_intersection_m(
      j_intersect_source, slope, 1.0 / HellwigCam::model_gamma(), g.limit_j_max, reach_max_m, g.limit_j_max);
  const double m = remap_m(M, boundary_m, reach_boundary_m, invert);
  return {j_intersect_source + m * slope, m};
}

}  // namespace

Aces2HueShape make_hue_shape(double cusp_j, double cusp_m, double gamma_top_inv, const Aces2GamutGeometry& g) {
  Aces2HueShape s;
  s.cusp_j = cusp_j;
  s.cusp_m = cusp_m;
  s.gamma_top_inv = gamma_top_inv;
  s.focus_j = lerp(cusp_j, g.mid_j, std::min(1.0, kCuspMidBlend - cusp_j / g.limit_j_max));
  s.analytical_threshold = lerp(cusp_j, g.limit_j_max, kFocusGainBlend);
  return s;
}

double aces2_focus_gain(double J, double analytical_threshold, const Aces2GamutGeometry& g) {
  double gain = g.limit_j_max * g.focus_distance;
  if (J > analytical_threshold) {
    // Above the threshold the gain grows towards J max (the inverse is then approximate).
    const double adjust =
        std::log10((g.limit_j_max - analytical_threshold) / std::max(0.0001, g.limit_j_max - J));
    gain *= adjust * adjust + 1.0;
  }
  return gain;
}

double aces2_solve_j_intersect(double J, double M, double focus_j, double max_j, double slope_gain) {
  const double m_scaled = M / slope_gain;
  const double a = m_scaled / focus_j;
  if (J < focus_j) {
    const double b = 1.0 - m_scaled;
    const double c = -J;
    return -2.0 * c / (b + std::sqrt(b * b - 4.0 * a * c));
  }
  const double b = -(1.0 + m_scaled + max_j * a);
  const double c = max_j * m_scaled + J;
  return -2.0 * c / (b - std::sqrt(b * b - 4.0 * a * c));
}

double aces2_compression_vector_slope(double intersect_j, double focus_j, double limit_j_max, double slope_gain) {
  const double direction = intersect_j < focus_j ? intersect_j : limit_j_max - intersect_j;
  return direction * (intersect_j - focus_j) / (focus_j * slope_gain);
}

double aces2_gamut_boundary_m(const Aces2HueShape& s, double limit_j_max, double gamma_top_inv,
                              double lower_hull_gamma_inv, double j_intersect_source, double slope,
                              double j_intersect_cusp) {
  const double lower = line_boundary_intersection_m(j_intersect_source, slope, lower_hull_gamma_inv, s.cusp_j,
                                                    s.cusp_m, j_intersect_cusp);
  // The upper hull, mirrored so that it starts at J max, with the slope negated.
  const double upper = line_boundary_intersection_m(limit_j_max - j_intersect_source, -slope, gamma_top_inv,
                                                    limit_j_max - s.cusp_j, s.cusp_m, limit_j_max - j_intersect_cusp);
  return smooth_min(lower, upper, s.cusp_m);
}

Vec2<double> aces2_gamut_compress_forward(double J, double M, double reach_max_m, const Aces2HueShape& s,
                                          const Aces2GamutGeometry& g) {
  if (J <= 0.0) return {0.0, 0.0};
  if (M <= 0.0 || J > g.limit_j_max) return {J, 0.0};
  return compress(J, M, J, reach_max_m, s, g, false);
}

Vec2<double> aces2_gamut_compress_inverse(double J, double M, double reach_max_m, const Aces2HueShape& s,
                                          const Aces2GamutGeometry& g) {
  if (J <= 0.0) return {0.0, 0.0};
  if (M <= 0.0 || J > g.limit_j_max) return {J, 0.0};
  double jx = J;
  if (jx > s.analytical_threshold) jx = compress(J, M, jx, reach_max_m, s, g, true).x;
  return compress(J, M, jx, reach_max_m, s, g, true);
}

}  // namespace prism::display
