#include "prism/display/aces_rrt.h"

#include <algorithm>
#include <cmath>

#include "prism/display/aces_common.h"
#include "prism/display/segmented_spline.h"

namespace prism::display {
namespace {

using namespace rrt;

// glow_fwd: extra gain for dark, saturated colours, fading out between 2/3 and 2 × mid.
double glow_gain(double yc, double gain, double mid) {
  if (yc <= 2.0 / 3.0 * mid) return gain;
  if (yc >= 2.0 * mid) return 0.0;
  return gain * (mid / yc - 0.5);
}

}  // namespace

Vec3d rrt_sweeteners(const Vec3d& in) {
  const AcesMatrices& m = aces_matrices();
  Vec3d aces = in;
  const double saturation = rgb_saturation(aces);
  const double s = sigmoid_shaper((saturation - 0.4) / 0.2);
  aces *= 1.0 + glow_gain(rgb_yc(aces), kGlowGain * s, kGlowMid);

  const double hue_weight =
      cubic_basis_shaper(center_hue(rgb_hue_degrees(aces), kRedHueDegrees), kRedWidthDegrees);
  aces.x += hue_weight * saturation * (kRedPivot - aces.x) * (1.0 - kRedScale);

  // Clamping before the matrix keeps saturated negatives from turning positive in AP1.
  for (int c = 0; c < 3; ++c) aces[c] = std::max(aces[c], 0.0);
  Vec3d rgb = m.ap0_to_ap1 * aces;
  for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c], 0.0, kHalfMax);
  static const Mat3 kDesat = saturation_matrix(kSatFactor, m.ap1_luminance);
  return kDesat * rgb;
}

Vec3d aces_rrt(const Vec3d& aces) {
  const Vec3d pre = rrt_sweeteners(aces);
  const Vec3d post{segmented_spline_c5_fwd(pre.x), segmented_spline_c5_fwd(pre.y), segmented_spline_c5_fwd(pre.z)};
  return aces_matrices().ap1_to_ap0 * post;
}

}  // namespace prism::display
