#pragma once
// The ACES 1.x segmented quadratic B-spline tone curves in log10–log10 space
// (aces-dev lib/ACESlib.Tonescales.ctl): C5 is the RRT's scene→OCES curve, C9 the
// SDR ODTs' OCES→cinema-luminance curve (48 nit white, 0.02 nit black).
namespace prism::display {

// RRT tone scale: ACES (AP1 rendering-space channel) → OCES luminance-like value.
double segmented_spline_c5_fwd(double x);

// ODT tone scale for the 48 nit cinema reference (ODT_48nits): OCES → luminance in nits.
double segmented_spline_c9_fwd(double x);

}  // namespace prism::display
