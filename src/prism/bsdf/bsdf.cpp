// Explicit instantiations for the integrator's spectrum sizes: N = 3 (RGB mode and
// 3-wavelength spectral), 4 and 8 wavelengths.
#include "prism/bsdf/bsdf.h"

namespace prism::bsdf {

template struct Bsdf<3>;
template struct Bsdf<4>;
template struct Bsdf<8>;

}  // namespace prism::bsdf
