#include "prism/display/agx.h"

#include <algorithm>
#include <cmath>

namespace prism::display {
namespace {

// The configuration's inset matrix (config.ocio, colour space "AgX Log", MatrixTransform,
// row-major, out = M · in): each primary moved toward white so that bright saturated light
// reaches the shoulder on all three channels and desaturates ("path to white").
constexpr double kInset[3][3] = {
    {0.842479062253094, 0.0784335999999992, 0.0792237451477643},
    {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
    {0.0423756549057051, 0.0784336, 0.879142973793104},
};

// log2 range of the encoding: middle grey 0.18 ± (10, 6.5) stops (AllocationTransform vars).
constexpr double kLog2Min = -12.47393;
constexpr double kLog2Max = 4.026069;

// The generator's sigmoid: through (x_pivot, y_pivot) with slope `slope`, reaching (0, 0)
// and (1, 1); toe and shoulder are the hyperbola x / (1 + x^p)^(1/p) scaled so that they
// meet those end points.
constexpr double kPivotX = 10.0 / 16.5;  // middle grey's place in the 16.5-stop encoding
constexpr double kPivotY = 0.5;          // middle grey's code value (0.5^2.2 ≈ 0.218 of white)
constexpr double kSlope = 2.0;
constexpr double kToePower = 3.0;
constexpr double kShoulderPower = 3.25;

// The scale of one limb: the curve's span on that side of the pivot, (dx, dy), so that the
// limb's hyperbola passes its end point.
double limb_scale(double dx, double dy, double power) {
  return std::pow(std::pow(kSlope * dx, -power) * (std::pow(kSlope * dx / dy, power) - 1.0), -1.0 / power);
}

double hyperbola(double t, double power) { return t / std::pow(1.0 + std::pow(t, power), 1.0 / power); }

}  // namespace

double agx_base_curve(double x) {
  x = std::clamp(x, 0.0, 1.0);
  double y;
  if (x >= kPivotX) {
    const double scale = limb_scale(1.0 - kPivotX, 1.0 - kPivotY, kShoulderPower);
    y = kPivotY + scale * hyperbola(kSlope * (x - kPivotX) / scale, kShoulderPower);
  } else {
    const double scale = limb_scale(kPivotX, kPivotY, kToePower);
    y = kPivotY - scale * hyperbola(kSlope * (kPivotX - x) / scale, kToePower);
  }
  // The end points come out within a few ulps of 0 and 1, either side: keep the code in [0, 1].
  return std::clamp(y, 0.0, 1.0);
}

Vec3d agx_base(const Vec3d& rec709_linear) {
  Vec3d in;
  for (int c = 0; c < 3; ++c) in[c] = std::isfinite(rec709_linear[c]) ? std::max(rec709_linear[c], 0.0) : 0.0;
  Vec3d out;
  for (int r = 0; r < 3; ++r) {
    const double v = kInset[r][0] * in[0] + kInset[r][1] * in[1] + kInset[r][2] * in[2];
    // log2 of 0 is −∞: the encoding clamps it to 0 as OpenColorIO's log of its smallest float does.
    const double log_encoded = v > 0.0 ? (std::log2(v) - kLog2Min) / (kLog2Max - kLog2Min) : 0.0;
    out[r] = agx_base_curve(log_encoded);
  }
  return out;
}

Vec3d agx_display_linear(const Vec3d& rec709_linear) {
  const Vec3d base = agx_base(rec709_linear);
  return {std::pow(base[0], 2.2), std::pow(base[1], 2.2), std::pow(base[2], 2.2)};
}

}  // namespace prism::display
