#pragma once
// AgX, Troy Sobotka's display rendering, as his sobotka/AgX OpenColorIO configuration
// defines its "AgX" view (the original AgX, from which Blender 4's AgX derives):
//
//   linear Rec.709, clamped at 0 (RangeTransform min 0)
//   → the inset matrix (AgX_compressed_matrix, the config's MatrixTransform literal)
//   → log2 encoding: (log2(x) − lo) / (hi − lo), clamped to [0, 1], with lo = log2(0.18·2^-10)
//     = −12.47393 and hi = log2(0.18·2^6.5) = 4.026069 (AllocationTransform lg2): 16.5 stops
//     around middle grey
//   → the base contrast curve (AgX_Default_Contrast.spi1d), whose output is a code value for
//     a display with a pure 2.2 EOTF
//
// The configuration ships the curve as a 4096-entry 1D LUT; its generator (AgX-S2O3's
// AgX.py, the sigmoid credited to Jed Smith) computes each entry in closed form, so here the
// curve is that closed form itself (agx_base_curve), not a table: with the generator's
// parameters (pivot at x = 10/16.5, y = 0.5; slope 2.0; toe and shoulder powers 3.0 and
// 3.25) it reproduces OpenColorIO's output through the LUT within 2e-7 of code (test
// AgxOracle: the LUT's linear interpolation between 4096 samples of a curve whose second
// derivative is below 10 adds at most 10/(8·4095²) ≈ 7e-8).
//
// Display light: base^2.2 relative to the display's white (100 nits), in Rec.709 primaries;
// the configuration's BT.1886 and Display P3 displays show that same light (encoded with
// γ 2.4, or converted to P3 primaries and encoded with γ 2.2).
#include "prism/core/vec.h"

namespace prism::display {

// The base contrast curve on the normalised log2 encoding x in [0, 1] (clamped), → [0, 1].
double agx_base_curve(double x);

// Linear Rec.709 scene light → the AgX base code value per channel (γ 2.2 display code).
Vec3d agx_base(const Vec3d& rec709_linear);

// Linear Rec.709 scene light → display-linear Rec.709 light relative to the display's white
// (agx_base^2.2), in [0, 1].
Vec3d agx_display_linear(const Vec3d& rec709_linear);

}  // namespace prism::display
