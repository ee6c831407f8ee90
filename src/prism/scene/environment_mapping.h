#pragma once
// Texture coordinates of environment maps (uv ∈ [0,1]², v = 0 the image's top row) and
// directions in the environment's own frame, for both parameterisations of
// EnvironmentMapping, with the Jacobian that turns a density over the image into a
// density over solid angle.
#include "prism/core/vec.h"
#include "prism/scene/light.h"

namespace prism {

// Unit direction (in the map's frame) → uv.
Vec2f environment_direction_to_uv(EnvironmentMapping mapping, const Vec3f& direction);

// uv → unit direction in the map's frame.
Vec3f environment_uv_to_direction(EnvironmentMapping mapping, Vec2f uv);

// dω / d(u v): steradians per unit of image area at uv. Equirectangular: 2π² sin θ
// (θ = π v); equal-area octahedral: 4π everywhere. A density p_uv over the image is
// p_ω = p_uv / this over the sphere. A function of uv.y alone in both mappings (callers
// may evaluate it once per image row).
float environment_solid_angle_per_uv_area(EnvironmentMapping mapping, Vec2f uv);

}  // namespace prism
