#pragma once
// Illuminance that an environment map sheds on a surface: E_v = ∫ L_v(ω) max(0, ω·n) dω
// over the sphere (lux, for texels in nits), the photometric definition (CIE S 017,
// 17-21-050 "illuminance"; the cosine-weighted integral of luminance). pbrt-v4's infinite
// light takes an `illuminance` in lux for a surface facing the light frame's +z and scales
// the map to give it; this is the integral that scaling divides by.
#include "prism/core/vec.h"
#include "prism/scene/light.h"
#include "prism/scene/texture.h"

namespace prism {

// The map's illuminance (lux per nit of texel value) on a surface with unit normal
// `normal` in the map's own frame: the midpoint rule over texel centres, each texel
// weighted by its solid angle (environment_solid_angle_per_uv_area / texel count), its
// luminance from linear RGB in the map's texel_space (grey for one- and two-channel images).
double environment_illuminance_lux(const TextureImage& map, EnvironmentMapping mapping, const Vec3f& normal);

}  // namespace prism
