#include "prism/bsdf/conductor_color.h"

#include <algorithm>

#include "prism/bsdf/fresnel.h"
#include "prism/bsdf/ior.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"
#include "prism/color/spectrum.h"

namespace prism::bsdf {

Vec3f conductor_f0_rec709(std::string_view name) {
  const ConductorIor ior = conductor_ior(name);
  const auto f0 = [&](double nm) {
    return static_cast<double>(fresnel_conductor(1.0f, static_cast<float>(ior.eta(nm)), static_cast<float>(ior.k(nm))));
  };
  // As a spectral render shows the metal under a white (flat) light: XYZ under E, adapted
  // to D65 (emission_spectrum.h's convention), so the GLB's base colour, upsampled by the
  // E-relative Jakob–Hanika table, films the same colour as the conductor itself.
  const Vec3d xyz = color::reflectance_to_xyz(f0, color::standard_illuminant(color::StandardIlluminant::e));
  const Vec3d rgb = color::spectral_xyz_to_rgb_matrix(color::color_space("srgb")) * xyz;
  return {static_cast<float>(std::clamp(rgb.x, 0.0, 1.0)), static_cast<float>(std::clamp(rgb.y, 0.0, 1.0)),
          static_cast<float>(std::clamp(rgb.z, 0.0, 1.0))};
}

}  // namespace prism::bsdf
