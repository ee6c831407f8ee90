#include "prism/display/hellwig_cam.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "prism/color/chromaticity.h"

namespace prism::display {
namespace {

constexpr double kReferenceLuminance = 100.0;  // cd/m² of RGB (1, 1, 1)
constexpr double kAdaptingLuminance = 100.0;   // L_A
constexpr double kBackgroundY = 20.0;          // Y_b
constexpr double kSurroundC = 0.59;            // dim surround
constexpr double kSurroundNc = 0.9;
constexpr double kCompressionOffset = 27.13;   // Hellwig 2022 eq. 10
constexpr double kExpansionLimit = 0.99;       // the Academy's clamp of the inverse
constexpr double kResponseScale = 400.0;       // CAM16's response range, 400 x^0.42 / (27.13 + x^0.42)

// The Academy's replacement of the CAM16 cone space, given as primaries and white, turned
// into a matrix by Lindbloom's derivation (columns S_i (x_i, y_i, z_i)/y_i with S solving
// RGB (1, 1, 1) → white). The white lies outside these "primaries'" triangle, so
// color::rgb_to_xyz_matrix (which refuses that for real RGB spaces) is not used.
Mat3 xyz_to_cam16_rgb() {
  const color::Chromaticity xy[3] = {{0.8336, 0.1735}, {2.3854, -1.4659}, {0.087, -0.125}};
  Vec3d columns[3];
  for (int i = 0; i < 3; ++i) columns[i] = color::xy_to_XYZ(xy[i]);
  const Mat3 unscaled = Mat3::from_columns(columns[0], columns[1], columns[2]);
  const Vec3d s = inverse(unscaled) * color::xy_to_XYZ({0.333, 0.333});
  return inverse(unscaled * Mat3::diagonal(s));
}

// CIECAM02/CAM16 luminance-level adaptation factor F_L for L_A.
double luminance_adaptation_factor() {
  const double k = 1.0 / (5.0 * kAdaptingLuminance + 1.0);
  const double k4 = k * k * k * k;
  return 0.2 * k4 * (5.0 * kAdaptingLuminance) +
         0.1 * (1.0 - k4) * (1.0 - k4) * std::cbrt(5.0 * kAdaptingLuminance);
}

double signed_compression(double v) { return std::copysign(hellwig_response_compression(std::abs(v)), v); }
double signed_expansion(double v) { return std::copysign(hellwig_response_expansion(std::abs(v)), v); }

}  // namespace

double hellwig_response_compression(double x) {
  const double p = std::pow(x, 0.42);
  return p / (kCompressionOffset + p);
}

double hellwig_response_expansion(double r) {
  const double r_limited = std::min(r, kExpansionLimit);
  return std::pow(kCompressionOffset * r_limited / (1.0 - r_limited), 1.0 / 0.42);
}

double HellwigCam::model_gamma() { return kSurroundC * (1.48 + std::sqrt(kBackgroundY / kReferenceLuminance)); }

double HellwigCam::pow_model_gamma(double A) { return std::pow(A, model_gamma()); }

double HellwigCam::j_to_achromatic(double J) {
  return std::pow(std::max(J, 0.0) / 100.0, 1.0 / model_gamma());
}

HellwigCam::HellwigCam(const Mat3& rgb_to_xyz) {
  const Mat3 m16 = xyz_to_cam16_rgb();
  const Vec3d xyz_white = rgb_to_xyz * Vec3d(kReferenceLuminance);
  const Vec3d cone_white = m16 * xyz_white;
  const double fl = luminance_adaptation_factor();
  fl_normalised_ = fl / kReferenceLuminance;
  // Complete adaptation (D = 1) folded together with F_L / 100 into one diagonal scale, so
  // that the adapted white's signals all equal F_L and compress to the same response.
  const Vec3d d_rgb = Vec3d(fl_normalised_ * xyz_white.y) / cone_white;
  rgb_to_cone_ = Mat3::diagonal(d_rgb) * m16 * rgb_to_xyz * Mat3::diagonal(Vec3d(kReferenceLuminance));
  cone_to_rgb_ = inverse(rgb_to_cone_);

  achromatic_white_j_ = hellwig_response_compression(fl);
  // A = 2R + G + B/20 normalised by the white's, a = R − 12G/11 + B/11, b = (R + G − 2B)/9,
  // with the responses back on CAM16's scale (× 400) and the opponent pair scaled by
  // 43 N_c, so that its length is M.
  const double white_response = hellwig_response_compression(fl);
  const double achromatic_white = (2.0 + 1.0 + 1.0 / 20.0) * white_response;
  const double opponent_scale = kResponseScale * 43.0 * kSurroundNc;
  response_to_aab_ = Mat3::from_columns({2.0 / achromatic_white, opponent_scale, opponent_scale / 9.0},
                                        {1.0 / achromatic_white, -12.0 / 11.0 * opponent_scale, opponent_scale / 9.0},
                                        {1.0 / 20.0 / achromatic_white, opponent_scale / 11.0, -2.0 / 9.0 * opponent_scale});
  aab_to_response_ = inverse(response_to_aab_);
}

Vec3d HellwigCam::rgb_to_aab(const Vec3d& rgb) const {
  const Vec3d cone = rgb_to_cone_ * rgb;
  const Vec3d response{signed_compression(cone.x), signed_compression(cone.y), signed_compression(cone.z)};
  return response_to_aab_ * response;
}

Vec3d HellwigCam::aab_to_rgb(const Vec3d& aab) const {
  const Vec3d response = aab_to_response_ * aab;
  const Vec3d cone{signed_expansion(response.x), signed_expansion(response.y), signed_expansion(response.z)};
  return cone_to_rgb_ * cone;
}

Vec3d HellwigCam::aab_to_jmh(const Vec3d& aab) const {
  if (aab.x <= 0.0) return {0.0, 0.0, 0.0};
  const double J = achromatic_to_j(aab.x);
  const double M = std::sqrt(aab.y * aab.y + aab.z * aab.z);
  double h = std::atan2(aab.z, aab.y) * (180.0 / std::numbers::pi);
  if (h < 0.0) h += 360.0;
  if (h >= 360.0) h = 0.0;  // −0 rounding up to 360
  return {J, M, h};
}

Vec3d HellwigCam::jmh_to_aab(double J, double M, double cos_h, double sin_h) const {
  return {j_to_achromatic(J), M * cos_h, M * sin_h};
}

Vec3d HellwigCam::jmh_to_rgb(const Vec3d& jmh) const {
  const double h = jmh.z * (std::numbers::pi / 180.0);
  return aab_to_rgb(jmh_to_aab(jmh.x, jmh.y, std::cos(h), std::sin(h)));
}

double HellwigCam::y_to_j(double Y) const {
  const double response = hellwig_response_compression(std::abs(Y) * fl_normalised_);
  return std::copysign(achromatic_to_j(response / achromatic_white_j_), Y);
}

double HellwigCam::achromatic_to_y(double A) const {
  return hellwig_response_expansion(achromatic_white_j_ * A) / fl_normalised_;
}

double HellwigCam::j_to_y(double J) const {
  return std::copysign(achromatic_to_y(j_to_achromatic(std::abs(J))), J);
}

}  // namespace prism::display
