#pragma once
// The ACES 1.x Reference Rendering Transform (aces-dev rrt/RRT.ctl), from ACES2065-1
// (AP0, scene-linear) to OCES (AP0, the RRT's output-referred encoding).
#include "prism/core/vec.h"

namespace prism::display {

// RRT constants (RRT.ctl / ACESlib.RRT_Common.ctl, published Academy data). Shared by the
// exact path (aces_rrt.cpp) and the float block kernel (aces_output_kernel.cpp).
namespace rrt {
inline constexpr double kGlowGain = 0.05;
inline constexpr double kGlowMid = 0.08;
inline constexpr double kRedScale = 0.82;
inline constexpr double kRedPivot = 0.03;
inline constexpr double kRedHueDegrees = 0.0;
inline constexpr double kRedWidthDegrees = 135.0;
inline constexpr double kSatFactor = 0.96;
}  // namespace rrt

// The RRT's "sweeteners" (ACESlib.RRT_Common.ctl rrt_sweeteners): glow, red modifier,
// clamp, AP0→AP1, global desaturation. Returns AP1 rendering-space RGB, ready for a
// per-channel tone scale. Order as in the CTL: the red modifier uses the saturation
// measured before the glow gain is applied.
Vec3d rrt_sweeteners(const Vec3d& aces);

// The full RRT: sweeteners, C5 tone scale per AP1 channel, back to AP0.
Vec3d aces_rrt(const Vec3d& aces);

}  // namespace prism::display
