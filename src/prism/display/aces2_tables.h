#pragma once
// The per-hue tables of the ACES 2.0 Output Transform, built once per (peak, limiting
// gamut) as aces-core lib/Lib.Academy.OutputTransform.ctl (init_ODTParams) and OpenColorIO's
// ACES2 fixed function build them, with the same sizes, sampling and search tolerances:
//  - reach M: for each whole degree of hue, the largest M at J = J max that the reach gamut
//    (AP1) still contains (bisection to 0.01);
//  - hues: 360 samples, as uniform as possible while hitting exactly the hues of the six
//    corners of the limiting gamut's cube at peak and of the reach gamut at J max;
//  - cusps: J and M of the limiting gamut's cusp at each of those hues (on the cube's edges
//    between corners, bisection to 1e-7), M widened by the cusp smoothing;
//  - upper hull gamma: per hue, the smallest exponent (searched in 0.4 steps up to 5, then
//    bisection to 1e-5) for which the approximate boundary lies outside the limiting gamut
//    at five lightnesses between the cusp and J max.
// Each table has one wrapped entry below and one above its 360 nominal ones.
#include <array>

#include "prism/display/aces2_gamut_compression.h"
#include "prism/display/hellwig_cam.h"

namespace prism::display {

inline constexpr int kAces2TableSize = 360;
using Aces2Table = std::array<double, kAces2TableSize + 2>;

struct Aces2ReachTable {
  Aces2Table m{};  // index 1 + i ↔ hue i degrees
  double at(double hue_degrees) const;
};
Aces2ReachTable make_aces2_reach_table(const HellwigCam& reach, double limit_j_max);

struct Aces2CuspTable {
  Aces2Table hue{}, cusp_j{}, cusp_m{}, gamma_top_inv{};
  // The hue's interpolated cusp and upper-hull exponent, with its focus J and threshold.
  Aces2HueShape shape(double hue_degrees, const Aces2GamutGeometry& g) const;
};
Aces2CuspTable make_aces2_cusp_table(const HellwigCam& reach, const HellwigCam& limit, double peak_nits,
                                     double forward_limit, const Aces2GamutGeometry& g);

}  // namespace prism::display
