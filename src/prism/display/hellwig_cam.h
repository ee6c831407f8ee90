#pragma once
// The colour appearance model of the ACES 2.0 Output Transforms: Hellwig & Fairchild's
// revision of CAM16 ("Brightness, lightness, colorfulness, and chroma in CIECAM02 and CAM16",
// Color Res. Appl. 47, 2022) with the Academy's modifications (ACES 2.0 "Output Transform
// technical details", aces-core lib/Lib.Academy.OutputTransform.ctl):
//  - the CAM16 cone matrix is replaced by a "primaries" set chosen for the rendering
//    (red 0.8336 0.1735, green 2.3854 −1.4659, blue 0.087 −0.125, white 0.333 0.333);
//  - full (D = 1) adaptation to the white of the RGB space being converted;
//  - a dim surround (F 0.9, c 0.59, N_c 0.9), L_A = 100 cd/m², Y_b = 20, and the model's
//    exponent c·z computed with Y_w = 100 (Y_b/Y_w = 0.2) for every space;
//  - the post-adaptation compression without the CAM16 0.1 offset and applied mirrored
//    to negative cone signals; its inverse saturates at 99 % of the compression's range;
//  - M is colourfulness without the eccentricity factor: M = 43 N_c √(a² + b²).
// RGB here is linear, with RGB (1, 1, 1) = the space's white at 100 cd/m² (reference
// luminance); Y is in cd/m². Hue h is in degrees, [0, 360).
#include "prism/core/mat3.h"
#include "prism/core/vec.h"

namespace prism::display {

class HellwigCam {
 public:
  // rgb_to_xyz: the space's matrix with RGB (1, 1, 1) → its white at Y = 1.
  explicit HellwigCam(const Mat3& rgb_to_xyz);

  // Achromatic response A (normalised: A = 1 at the reference white) and opponent a, b
  // (already scaled by 43 N_c, so that M = |(a, b)|).
  Vec3d rgb_to_aab(const Vec3d& rgb) const;
  Vec3d aab_to_rgb(const Vec3d& aab) const;
  // J, M, h; A ≤ 0 gives (0, 0, 0).
  Vec3d aab_to_jmh(const Vec3d& aab) const;
  Vec3d rgb_to_jmh(const Vec3d& rgb) const { return aab_to_jmh(rgb_to_aab(rgb)); }
  // J, M and the hue's cosine and sine (so that callers can reuse them) → A, a, b.
  Vec3d jmh_to_aab(double J, double M, double cos_h, double sin_h) const;
  Vec3d jmh_to_rgb(const Vec3d& jmh) const;

  // Lightness of an achromatic colour of luminance Y (cd/m²) and back; odd functions.
  double y_to_j(double Y) const;
  double j_to_y(double J) const;
  // Achromatic response ↔ luminance (A ≥ 0).
  double achromatic_to_y(double A) const;

  // The model exponent c·z = 0.59 (1.48 + √0.2).
  static double model_gamma();
  static double achromatic_to_j(double A) { return 100.0 * pow_model_gamma(A); }
  static double j_to_achromatic(double J);

 private:
  static double pow_model_gamma(double A);
  Mat3 rgb_to_cone_;       // RGB → adapted, F_L-scaled cone signals (D_RGB · M16 · 100)
  Mat3 cone_to_rgb_;
  Mat3 response_to_aab_;   // compressed cone responses → A, a, b
  Mat3 aab_to_response_;
  double fl_normalised_;   // F_L / 100
  double achromatic_white_j_;  // compressed response of Y = 100 (A_w for J)
};

// Post-adaptation non-linear response compression of Hellwig 2022 eq. 10 without the
// offset, normalised to [0, 1): x^0.42 / (27.13 + x^0.42), and its inverse (x ≥ 0). The
// inverse clamps its argument at 0.99, as the Academy's implementation does.
double hellwig_response_compression(double x);
double hellwig_response_expansion(double r);

}  // namespace prism::display
