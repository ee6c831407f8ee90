#pragma once
// Emission spectra from RGB light colours, by the seed renderer's rule:
//   1. the light's working-space RGB is converted to XYZ and chromatically adapted
//      (Bradford) from the working white to illuminant E;
//   2. a Jakob–Hanika sigmoid polynomial s(λ) is fitted to that colour relative to E
//      (our Gauss–Newton fitter, directly per light; lights are few) — scaled to half the
//      largest channel, so it sits well inside the [0, 1] range a sigmoid can reach;
//   3. the spectrum is L(λ) = K s(λ) with K chosen so that the film shows the requested
//      luminance in nits: 683 times the Y of ∫ L (x̄, ȳ, z̄) dλ (trapezoid, 1 nm, 380–780 nm)
//      adapted back from E to the working white (for greys: 683 ∫ L ȳ dλ itself).
// Consequence, and the convention a spectral film must follow: an equal-energy spectrum is
// the neutral of a spectral render. A working-space white light becomes a flat spectrum,
// whose XYZ is E's; converting rendered XYZ to working RGB must adapt E → working white
// (spectral_xyz_to_rgb_matrix). Without that adaptation a D65 working space shows E's
// white as reddish (tests/color/emission_spectrum_test.cpp).
#include "prism/color/color_space.h"
#include "prism/color/sigmoid_polynomial.h"
#include "prism/core/mat3.h"
#include "prism/core/vec.h"

namespace prism::color {

struct EmissionSpectrum {
  SigmoidPolynomial shape;
  double scale = 0.0;  // K: W·m⁻²·sr⁻¹·nm⁻¹ per unit of shape
  double operator()(double wavelength_nm) const { return scale * shape(wavelength_nm); }
};

// Negative RGB components are clamped to 0 (no negative light); a black colour or zero
// luminance gives the zero spectrum. Negative or non-finite luminance: UsageError.
EmissionSpectrum emission_spectrum(const Vec3d& rgb, const ColorSpace& working, double luminance_nits);

// Bradford adaptation of XYZ from the working white to E (step 1) and back.
Mat3 working_to_e_adaptation(const ColorSpace& working);
// Rendered (E-neutral) XYZ → working RGB: xyz_to_rgb · Bradford(E → working white).
Mat3 spectral_xyz_to_rgb_matrix(const ColorSpace& working);

}  // namespace prism::color
