#include "prism/display/aces_common.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"

namespace prism::display {

const AcesMatrices& aces_matrices() {
  static const AcesMatrices m = [] {
    const color::ColorSpace& ap0 = color::color_space("aces2065-1");
    const color::ColorSpace& ap1 = color::color_space("acescg");
    AcesMatrices r;
    r.ap0_to_ap1 = color::conversion_matrix(ap0, ap1);  // same white: no adaptation
    r.ap1_to_ap0 = color::conversion_matrix(ap1, ap0);
    r.ap1_to_xyz = ap1.rgb_to_xyz;
    r.xyz_to_ap1 = ap1.xyz_to_rgb;
    r.ap1_luminance = ap1.rgb_to_xyz.row(1);
    r.d60_to_d65 = color::adaptation_matrix(color::xy_to_XYZ(color::kWhiteAces),
                                            color::xy_to_XYZ(color::kWhiteD65), color::Cat::bradford);
    return r;
  }();
  return m;
}

Mat3 saturation_matrix(double saturation, const Vec3d& w) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = (1.0 - saturation) * w[j] + (i == j ? saturation : 0.0);
  return m;
}

double rgb_saturation(const Vec3d& rgb) {
  constexpr double kTiny = 1e-10;
  const double hi = std::max({rgb.x, rgb.y, rgb.z}), lo = std::min({rgb.x, rgb.y, rgb.z});
  return (std::max(hi, kTiny) - std::max(lo, kTiny)) / std::max(hi, 1e-2);
}

double rgb_yc(const Vec3d& rgb) {
  constexpr double kRadiusWeight = 1.75;
  const double r = rgb.x, g = rgb.y, b = rgb.z;
  // The radicand is ½·Σ(differences²) ≥ 0; the clamp only absorbs rounding.
  const double chroma = std::sqrt(std::max(0.0, b * (b - g) + g * (g - r) + r * (r - b)));
  return (b + g + r + kRadiusWeight * chroma) / 3.0;
}

double rgb_hue_degrees(const Vec3d& rgb) {
  if (rgb.x == rgb.y && rgb.y == rgb.z) return std::numeric_limits<double>::quiet_NaN();
  double hue = (180.0 / std::numbers::pi) *
               std::atan2(std::sqrt(3.0) * (rgb.y - rgb.z), 2.0 * rgb.x - rgb.y - rgb.z);
  if (hue < 0.0) hue += 360.0;
  return hue;
}

double sigmoid_shaper(double x) {
  const double t = std::max(1.0 - std::fabs(x / 2.0), 0.0);
  const double sign = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
  return (1.0 + sign * (1.0 - t * t)) / 2.0;
}

double cubic_basis_shaper(double x, double width) {
  // NaN (achromatic hue) fails both comparisons and yields 0, as in the CTL.
  if (!(x > -width / 2.0 && x < width / 2.0)) return 0.0;
  const double knot_coord = (x + width / 2.0) * 4.0 / width;
  const int j = static_cast<int>(knot_coord);
  const double t = knot_coord - j;
  // The four pieces of the uniform cubic B-spline basis, leftmost piece first.
  double y = 0.0;
  switch (j) {
    case 0: y = t * t * t / 6.0; break;
    case 1: y = (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0; break;
    case 2: y = (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0; break;
    case 3: y = (-t * t * t + 3.0 * t * t - 3.0 * t + 1.0) / 6.0; break;
    default: y = 0.0;
  }
  return y * 1.5;
}

double center_hue(double hue, double center) {
  double h = hue - center;
  if (h < -180.0) h += 360.0;
  else if (h > 180.0) h -= 360.0;
  return h;
}

}  // namespace prism::display
