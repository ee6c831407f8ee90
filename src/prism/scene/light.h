#pragma once
// Non-geometric lights in physical units (emissive triangles are materials' Emission).
#include <cstdint>
#include <string>

#include "prism/core/transform.h"
#include "prism/core/vec.h"
#include "prism/scene/material.h"

namespace prism {

enum class LightType : std::uint8_t {
  point,        // intensity: luminous intensity in candela (loaders convert lumens: I = Φ / 4π)
  spot,         // intensity: candela on the axis; smooth falloff between inner and outer cone
  directional,  // intensity: illuminance in lux on a surface facing the light
  environment,  // intensity: luminance scale in nits applied to the (linear) texture
};

// How an environment texture's uv maps to directions in the light's own frame
// (scene/environment_mapping.h has both maps and their Jacobians).
enum class EnvironmentMapping : std::uint8_t {
  equirectangular,        // v = θ/π from +y, u = (φ + π)/2π with φ = atan2(z, x)
  equal_area_octahedral,  // Clarberg 2008 as pbrt-v4 uses it: square image, +z at the centre
};

struct Light {
  std::string name;
  LightType type = LightType::point;
  Vec3f position{0.0f};
  Vec3f direction{0.0f, -1.0f, 0.0f};  // spot axis / direction light travels (directional)
  Vec3f color{1.0f};
  ColorPickerSpace color_space = ColorPickerSpace::srgb;
  float intensity = 1.0f;               // unit depends on type, see LightType
  // Relative spectral power distribution instead of a colour (scene/spectral_inputs.h);
  // `color` then holds its Rec.709 approximation.
  std::optional<color::PiecewiseLinearSpectrum> spectrum;
  float spot_inner_angle_degrees = 30.0f;
  float spot_outer_angle_degrees = 45.0f;
  float angular_diameter_degrees = 0.0f;  // directional: 0 = delta light; the Sun is ≈ 0.53
  int environment_texture = -1;           // environment: texture index (-1: constant)
  EnvironmentMapping environment_mapping = EnvironmentMapping::equirectangular;
  Transform environment_to_world;         // environment: orientation

  bool operator==(const Light&) const = default;
};

}  // namespace prism
