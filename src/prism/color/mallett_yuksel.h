#pragma once
// Spectral primary decomposition for sRGB reflectances: Mallett & Yuksel 2019, "Spectral
// Primary Decomposition for Rendering with sRGB Reflectance" (EGSR). Three basis spectra
// b_r, b_g, b_b ≥ 0 with b_r + b_g + b_b = 1 at every wavelength, chosen so that under D65
// with the CIE 1931 observer b_r, b_g, b_b have exactly the sRGB primaries' XYZ. Then
// s = r b_r + g b_g + b b_b reproduces any linear sRGB albedo in [0, 1]³ and, being a
// convex-style combination, stays within [0, max(r, g, b)] ⊂ [0, 1].
// Basis: the authors' published table (data/spectral_basis/mallett_yuksel_2019/, MIT).
#include "prism/color/spectrum.h"
#include "prism/core/vec.h"

namespace prism::color {

struct MallettYukselBasis {
  DenseSpectrum r, g, b;  // 380–780 nm at 5 nm, linearly interpolated
};

// The embedded basis. The table's columns sum to 1 within its printed precision (1e-5);
// they are divided by their sum at each wavelength on load so the partition of unity — and
// with it the [0, 1] bound — holds to rounding.
const MallettYukselBasis& mallett_yuksel_basis();

// The weights a spectral render gives the basis for a linear sRGB albedo. The basis
// reproduces sRGB under D65, but Prism lights a spectral scene's white with the flat
// spectrum (illuminant E, the emission rule of emission_spectrum.h) and its film adapts
// E → D65 by Bradford; seen that way the basis films as a matrix A that is not the identity
// (b_r films with red 1.064, b_g with red −0.069; the Cornell box's red wall (0.63, 0.065,
// 0.05) filmed as (0.666, 0.067, 0.051)). The weights are A⁻¹ · albedo, each clamped to
// [0, 1] so that s stays within [0, 1], with A's rows scaled so that white (1, 1, 1) keeps
// s = 1: exact, up to that 1e-4 scaling, inside the cube A maps onto; for the sRGB
// primaries themselves a weight leaves [0, 1] by at most 0.0065 and is clipped.
Vec3d mallett_yuksel_weights_under_e(Vec3d linear_srgb);

// The reflectance spectrum r b_r + g b_g + b b_b of weights (r, g, b); components clamped
// to [0, 1]. With the albedo itself as weights it is the authors' decomposition (exact under
// D65); the renderer passes mallett_yuksel_weights_under_e.
class MallettYukselSpectrum {
 public:
  explicit MallettYukselSpectrum(Vec3d linear_srgb);
  double operator()(double wavelength_nm) const;

 private:
  Vec3d rgb_;
};

}  // namespace prism::color
