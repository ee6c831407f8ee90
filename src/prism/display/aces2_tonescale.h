#pragma once
// The ACES 2.0 tonescale (Daniele Siragusano's and Evo's curve as the Academy's Output
// Transforms VWG adopted it; ACES 2.0 "Output Transform technical details", aces-core
// lib/Lib.Academy.Tonescale.ctl): a Michaelis–Menten-style compression with a power
// (contrast g = 1.15) followed by a quadratic toe (flare t_1 = 0.04), whose constants
// follow from the display's peak luminance n so that scene 0.18 lands on
// 10.013 · (1 + 0.14 log2(n / 100)) cd/m² and scene r_hit (128 … 896) reaches the peak.
// Luminances are in cd/m² with scene-referred 1.0 = 100 cd/m².
namespace prism::display {

struct Aces2Tonescale {
  explicit Aces2Tonescale(double peak_luminance_nits);

  double forward(double scene_y) const;   // scene Y → display Y, cd/m²
  double inverse(double display_y) const; // display Y (clamped to [0, peak]) → scene Y

  double peak_nits;
  double log_peak;       // log10(peak / 100)
  double grey_display;   // c_t: display luminance of scene 0.18, relative to 100 cd/m²
  double forward_limit;  // 8 r_hit: the largest AP1 value the output transform accepts
  double g, t_1, s_2, m_2, inverse_limit;
};

}  // namespace prism::display
