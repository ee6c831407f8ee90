#pragma once
// Our Gauss–Newton fitter for the Jakob & Hanika 2019 sigmoid-polynomial model, and the
// coefficient-table generator built on it. As in the paper (§4), the residual is the
// difference in CIELAB between the target colour and the colour of the sigmoid spectrum
// seen as a reflectance under the fit illuminant, the unknowns are the three polynomial
// coefficients over a normalised wavelength t = (λ − 380)/400 ∈ [0, 1] (better
// conditioned than nm), and the system is square (3 residuals, 3 unknowns), so each
// Gauss–Newton step solves J Δc = −r exactly; a step that does not reduce |r| is halved.
#include <array>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/color/sigmoid_polynomial.h"
#include "prism/color/spectrum.h"
#include "prism/core/mat3.h"

namespace prism::color {

using NormalizedCoefficients = std::array<double, 3>;  // of t², t, 1, t = (λ − 380)/400

SigmoidPolynomial to_wavelength_nm(const NormalizedCoefficients& c);

struct JakobHanikaFitResult {
  NormalizedCoefficients coefficients{};
  double delta_e = 0.0;  // final CIE76 residual
  int iterations = 0;
  bool converged = false;
};

class JakobHanikaFitter {
 public:
  // `illuminant` is the light the reflectance is seen under; XYZ are normalised so that
  // reflectance 1 has Y = 1, and CIELAB uses that XYZ as reference white. The quadrature
  // is the trapezoid rule over [380, 780] nm at `step_nm`.
  explicit JakobHanikaFitter(const DenseSpectrum& illuminant, double step_nm = 1.0);

  // XYZ of the sigmoid spectrum under the illuminant (Y = 1 for reflectance 1).
  Vec3d xyz(const NormalizedCoefficients& c) const;
  const Vec3d& white_xyz() const { return white_xyz_; }

  // Fits the target XYZ (same normalisation) starting from `initial`.
  JakobHanikaFitResult fit(const Vec3d& target_xyz, const NormalizedCoefficients& initial,
                           int max_iterations = 50, double tolerance_delta_e = 1e-6) const;

 private:
  // XYZ and ∂XYZ/∂c (columns) in one pass.
  void evaluate(const NormalizedCoefficients& c, Vec3d& xyz, Mat3& jacobian) const;

  std::vector<double> t_;                   // normalised wavelengths of the quadrature nodes
  std::vector<Vec3d> weights_;              // node weight × illuminant × CMF / ∫ illuminant ȳ
  Vec3d white_xyz_{};
};

// The coefficient table of one RGB space (the layout of the paper's supplementary code):
// for each largest channel l ∈ {r, g, b}, a res³ grid over (z, y, x) where z is the largest
// channel's value and x, y ∈ [0, 1] are the other two channels (in cyclic order) divided
// by z. All three axes are sampled at smoothstep(k/(res−1)), denser near 0 and 1. The paper
// spaces z by smoothstep(smoothstep(·)) and x, y uniformly; for the wide-gamut spaces the
// coefficients change fastest near the optimal-colour boundary — a channel near 0
// (saturated colours), two near-equal largest channels (bright yellows, cyans, magentas,
// where the best spectrum changes from a plateau to a notch) and mid-bright saturated z —
// and this spacing cut the round-trip error there severalfold at the same resolution (see
// tests/color/jakob_hanika_test.cpp). Entries are nm-space coefficients (c₀, c₁, c₂) as float.
struct JakobHanikaTableData {
  int resolution = 0;
  std::vector<float> scale;         // [res]
  std::vector<float> coefficients;  // [3][res][res][res][3]: l, z, y, x, coefficient
};

struct JakobHanikaTableStats {
  long fits = 0;
  long not_converged = 0;
  double max_delta_e = 0.0;  // worst residual over the grid (out-of-locus corners dominate)
};

double jakob_hanika_scale(int k, int resolution);         // z of slice k
double jakob_hanika_chroma_node(int i, int resolution);   // x (or y) of node i

// Fits every grid point of the table for an RGB space with matrix `rgb_to_xyz` (white
// Y = 1) seen under `illuminant`. Parallel over grid columns (oneTBB).
JakobHanikaTableData generate_jakob_hanika_table(const Mat3& rgb_to_xyz, const DenseSpectrum& illuminant,
                                                 int resolution, JakobHanikaTableStats* stats = nullptr);

// What Prism's embedded tables fit. A spectral render's neutral is illuminant E: a white
// light of any colour space becomes the flat spectrum (the emission rule,
// emission_spectrum.h), and the film adapts E to the working white by Bradford
// (spectral_xyz_to_rgb_matrix). So the reflectance of an RGB must reproduce that RGB when
// lit by E and adapted the same way, i.e. have the CIE XYZ under E
//   jakob_hanika_target_xyz_matrix(space) · rgb = Bradford(white → E) · rgb_to_xyz · rgb.
// The paper (and pbrt-v4) fit under the space's own white instead (D65 for sRGB); under
// Prism's E-white lights such a table rendered the Cornell box's green wall (0.14, 0.45,
// 0.091) as (0.116, 0.452, 0.086) and its red (0.63, 0.065, 0.05) as (0.675, 0.064, 0.050):
// illuminant metamerism between D65 and E, which no von Kries adaptation undoes.
Mat3 jakob_hanika_target_xyz_matrix(const ColorSpace& space);
// The table of `space` fitted that way: under illuminant E, to the targets above.
JakobHanikaTableData generate_jakob_hanika_table(const ColorSpace& space, int resolution,
                                                 JakobHanikaTableStats* stats = nullptr);

// The RGB of grid point (l, k, j, i) (the colour its coefficients were fitted to).
Vec3d jakob_hanika_grid_rgb(int l, int k, int j, int i, int resolution);

}  // namespace prism::color
