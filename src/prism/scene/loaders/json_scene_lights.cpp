// prism-scene/1: lights in photometric units, the environment, and emission given as power.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/loaders/json_scene_reader.h"
#include "prism/scene/spectral_inputs.h"

namespace prism::loaders {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Vec3f read_direction(const JsonValue& value) {
  const Vec3f d = value.as_vec3();
  const float len = length(d);
  if (!(len > 0.0f) || !std::isfinite(len)) value.fail("expected a non-zero direction");
  return d / len;
}

// Luminous intensity (cd) of a point or spot light from the flux it is given in lumens:
// a point light spreads Φ over 4π sr; a spot light over the cone up to the middle of its
// falloff, 2π(1 − (cos θ_inner + cos θ_outer)/2) sr (the convention pbrt-v4 uses).
float intensity_from_power(const Light& light, float power_lm) {
  if (light.type == LightType::point) return power_lm / (4.0f * kPi);
  const float deg = kPi / 180.0f;
  const float cos_mid = 0.5f * (std::cos(light.spot_inner_angle_degrees * deg) + std::cos(light.spot_outer_angle_degrees * deg));
  return power_lm / (2.0f * kPi * std::max(1.0f - cos_mid, 1e-6f));
}

// Area of a mesh's triangles after a transform (scene units²).
double transformed_area(const TriangleMesh& mesh, const Transform& t) {
  double area = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vec3d a(t.apply_point(mesh.positions[mesh.indices[i]]));
    const Vec3d b(t.apply_point(mesh.positions[mesh.indices[i + 1]]));
    const Vec3d c(t.apply_point(mesh.positions[mesh.indices[i + 2]]));
    area += 0.5 * length(cross(b - a, c - a));
  }
  return area;
}

}  // namespace

void JsonSceneReader::read_light_color(const JsonValue& value, Light& light) const {
  light.color = value.get_vec3("color", Vec3f(1.0f));
  if (min(light.color, Vec3f(0.0f)) != Vec3f(0.0f)) value["color"].fail("colour components must not be negative");
  if (auto s = value.find("color_space")) light.color_space = read_color_picker_space(*s);
  if (auto s = value.find("spectrum")) {
    if (value.has("color") || value.has("color_space")) value.fail("give either 'color' or 'spectrum', not both");
    set_emission_spectrum(light, read_spectrum(*s, SpectrumUse::emission));
  }
}

void JsonSceneReader::read_light(const JsonValue& value) {
  const LightType type = value["type"].as_enum(kLightTypeNames);
  if (type == LightType::environment) return read_environment(value);
  Light light;
  light.type = type;
  light.name = value.get_string("name", fmt::format("light{}", scene.lights.size()));
  read_light_color(value, light);
  if (type == LightType::directional) {
    value.expect_keys({"type", "name", "color", "color_space", "spectrum", "direction", "illuminance_lux",
                       "angular_diameter_degrees"});
    light.direction = read_direction(value["direction"]);
    light.intensity = value["illuminance_lux"].as_float(0.0f, 1e7f);
    light.angular_diameter_degrees = value.get_float("angular_diameter_degrees", 0.0f, 0.0f, 90.0f);
    scene.lights.push_back(std::move(light));
    return;
  }
  if (type == LightType::point) {
    value.expect_keys({"type", "name", "color", "color_space", "spectrum", "position", "intensity_cd", "power_lm"});
  } else {
    value.expect_keys({"type", "name", "color", "color_space", "spectrum", "position", "direction", "target",
                       "intensity_cd",
                       "power_lm", "inner_angle_degrees", "outer_angle_degrees"});
    if (value.has("direction") == value.has("target")) value.fail("give exactly one of 'direction' and 'target'");
    light.position = value["position"].as_vec3();
    if (auto d = value.find("direction")) light.direction = read_direction(*d);
    if (auto t = value.find("target")) {
      const Vec3f d = t->as_vec3() - light.position;
      if (!(length(d) > 0.0f)) t->fail("the target coincides with the position");
      light.direction = normalize(d);
    }
    light.spot_outer_angle_degrees = value.get_float("outer_angle_degrees", light.spot_outer_angle_degrees, 0.0f, 180.0f);
    light.spot_inner_angle_degrees =
        value.get_float("inner_angle_degrees", std::min(light.spot_inner_angle_degrees, light.spot_outer_angle_degrees),
                        0.0f, light.spot_outer_angle_degrees);
  }
  light.position = value["position"].as_vec3();
  if (value.has("intensity_cd") == value.has("power_lm")) value.fail("give exactly one of 'intensity_cd' and 'power_lm'");
  if (auto i = value.find("intensity_cd")) light.intensity = i->as_float(0.0f, 1e12f);
  if (auto p = value.find("power_lm")) light.intensity = intensity_from_power(light, p->as_float(0.0f, 1e13f));
  scene.lights.push_back(std::move(light));
}

void JsonSceneReader::read_environment(const JsonValue& value) {
  value.expect_keys(
      {"type", "name", "color", "color_space", "spectrum", "luminance_nits", "texture", "mapping", "transform"});
  Light light;
  light.type = LightType::environment;
  light.name = value.get_string("name", "environment");
  // A constant sky has a colour or a spectrum; a map's texels are its colours.
  if (value.has("texture"))
    for (const char* key : {"color", "color_space", "spectrum"})
      if (value.has(key))
        value[key].fail("an environment with a 'texture' takes no colour: its texels are its colours");
  read_light_color(value, light);
  light.intensity = value["luminance_nits"].as_float(0.0f, 1e12f);
  // An OpenEXR sky keeps its file's gamut (the first of Rec.709, Rec.2020 and ACEScg that
  // holds its primaries): an ACEScg HDRI's colours outside Rec.709 light the scene.
  if (auto t = value.find("texture"))
    light.environment_texture = read_texture(*t, TextureEncoding::srgb, {}, TextureContent::color_own_gamut);
  if (auto m = value.find("mapping")) {
    light.environment_mapping = m->as_enum<EnvironmentMapping>(
        {{"equirectangular", EnvironmentMapping::equirectangular},
         {"equal-area-octahedral", EnvironmentMapping::equal_area_octahedral}});
    if (light.environment_mapping == EnvironmentMapping::equal_area_octahedral && light.environment_texture >= 0) {
      const TextureImage& image = textures.image(light.environment_texture);  // its size is checked here
      if (image.width != image.height)
        m->fail(fmt::format("an equal-area-octahedral map must be square (the texture is {}×{})", image.width,
                            image.height));
    }
  }
  if (auto t = value.find("transform")) light.environment_to_world = read_transform(*t);
  for (const Light& l : scene.lights)
    if (l.type == LightType::environment) value.fail("the scene already has an environment");
  scene.lights.push_back(std::move(light));
}

// Φ = π L A for a Lambertian emitter (one side; two-sided emitters radiate 2π L A), with
// A the emitting area in m² over every placement of every mesh using the material.
void JsonSceneReader::finish_emission_power() {
  for (const auto& [material, power_lm] : emission_power_lm) {
    double area = 0.0;
    if (scene.instances.empty()) {
      for (const auto& mesh : scene.meshes)
        if (mesh.material == material) area += transformed_area(mesh, Transform{});
    } else {
      for (const auto& instance : scene.instances)
        if (scene.meshes[instance.mesh].material == material)
          area += transformed_area(scene.meshes[instance.mesh], instance.object_to_world);
    }
    Material& m = scene.materials[material];
    const double area_m2 = area * static_cast<double>(meters_per_unit) * meters_per_unit;
    if (!(area_m2 > 0.0))
      throw SceneError(fmt::format("{}: material '{}': emission power_lm needs emitting geometry, but no triangle uses it",
                                   document.source, m.name));
    const double sides = m.emission.two_sided ? 2.0 : 1.0;
    const double nits = power_lm / (std::numbers::pi * area_m2 * sides);
    if (!std::isfinite(nits) || nits > 1e15)
      throw SceneError(fmt::format("{}: material '{}': emission power_lm gives {} nits", document.source, m.name, nits));
    m.emission.luminance_nits = static_cast<float>(nits);
  }
}

}  // namespace prism::loaders
