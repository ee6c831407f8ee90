// The emission rule (see emission_spectrum.h).
#include "prism/color/emission_spectrum.h"

#include <algorithm>
#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/illuminants.h"
#include "prism/color/jakob_hanika_fit.h"
#include "prism/color/spectrum.h"
#include "prism/core/error.h"

namespace prism::color {

Mat3 working_to_e_adaptation(const ColorSpace& working) {
  return adaptation_matrix(white_XYZ(working), xy_to_XYZ(kWhiteE), Cat::bradford);
}

Mat3 spectral_xyz_to_rgb_matrix(const ColorSpace& working) {
  return working.xyz_to_rgb * adaptation_matrix(xy_to_XYZ(kWhiteE), white_XYZ(working), Cat::bradford);
}

EmissionSpectrum emission_spectrum(const Vec3d& rgb_in, const ColorSpace& working, double luminance_nits) {
  if (!(luminance_nits >= 0.0) || !std::isfinite(luminance_nits))
    throw UsageError("luminance must be a finite, non-negative number of nits");
  const Vec3d rgb = max(rgb_in, Vec3d(0.0));
  const double largest = max_component(rgb);
  if (!(largest > 0.0) || luminance_nits == 0.0) return {SigmoidPolynomial::constant(0.0), 0.0};

  static const JakobHanikaFitter fitter(standard_illuminant(StandardIlluminant::e));
  const Vec3d target = working_to_e_adaptation(working) * (working.rgb_to_xyz * (rgb / (2.0 * largest)));
  // Continuation from the grey of the same luminance: each step starts from the previous
  // solution, so saturated colours are reached without Gauss–Newton wandering off.
  const Vec3d grey = fitter.white_xyz() * target.y;
  NormalizedCoefficients c{0.0, 0.0, SigmoidPolynomial::constant(std::clamp(target.y, 1e-6, 1.0 - 1e-6)).c2};
  constexpr int kSteps = 8;
  for (int step = 1; step <= kSteps; ++step) {
    const double t = double(step) / kSteps;
    c = fitter.fit(grey * (1.0 - t) + target * t, c).coefficients;
  }
  EmissionSpectrum out{to_wavelength_nm(c), 1.0};
  // Normalise the luminance the film will show. The film adapts the spectrum's E-relative
  // XYZ back to the working white (spectral_xyz_to_rgb_matrix), and a Bradford adaptation
  // keeps Y only for the white itself: an orange light's E-relative Y is about 0.6 % above
  // its Y under D65, so normalising the E-relative Y filmed such lights that much dark.
  const Vec3d filmed = adaptation_matrix(xy_to_XYZ(kWhiteE), white_XYZ(working), Cat::bradford) * spectrum_to_xyz(out);
  out.scale = luminance_nits / (kMaxLuminousEfficacyLmPerW * filmed.y);
  return out;
}

}  // namespace prism::color
