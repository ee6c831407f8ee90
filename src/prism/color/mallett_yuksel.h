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

// The reflectance spectrum of a linear sRGB albedo; components clamped to [0, 1].
class MallettYukselSpectrum {
 public:
  explicit MallettYukselSpectrum(Vec3d linear_srgb);
  double operator()(double wavelength_nm) const;

 private:
  Vec3d rgb_;
};

}  // namespace prism::color
