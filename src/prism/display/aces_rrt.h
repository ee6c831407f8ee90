#pragma once
// The ACES 1.x Reference Rendering Transform (aces-dev rrt/RRT.ctl), from ACES2065-1
// (AP0, scene-linear) to OCES (AP0, the RRT's output-referred encoding).
#include "prism/core/vec.h"

namespace prism::display {

// The RRT's "sweeteners" (ACESlib.RRT_Common.ctl rrt_sweeteners): glow, red modifier,
// clamp, AP0→AP1, global desaturation. Returns AP1 rendering-space RGB, ready for a
// per-channel tone scale. Order as in the CTL: the red modifier uses the saturation
// measured before the glow gain is applied.
Vec3d rrt_sweeteners(const Vec3d& aces);

// The full RRT: sweeteners, C5 tone scale per AP1 channel, back to AP0.
Vec3d aces_rrt(const Vec3d& aces);

}  // namespace prism::display
