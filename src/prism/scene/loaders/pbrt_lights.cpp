// pbrt-v4 lights → Prism lights in photometric units. pbrt-v4 normalises every light
// spectrum to unit luminance before applying `scale` (an RGB colour keeps its own
// luminance), so a colour's CIE Y times `scale` is taken as candela (point, spot), lux
// (distant) or nits (infinite, area lights). `power` is taken in the same photometric
// scale (lumens).
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/emission.h"
#include "prism/scene/environment_illuminance.h"
#include "prism/scene/loaders/pbrt_builder.h"
#include "prism/scene/spectral_inputs.h"

namespace prism::loaders {
namespace {

struct LightColor {
  Vec3f color{1.0f};
  ColorPickerSpace space = ColorPickerSpace::srgb;
  float luminance = 1.0f;
  std::optional<color::PiecewiseLinearSpectrum> spectrum;  // rendered as data (PbrtParams::get_spectrum)
};

// "scale", which multiplies every light's emission: negative (or NaN) is an error at it.
double light_scale(const PbrtParams& p) {
  const double scale = p.get_float("scale", 1.0);
  if (!(scale >= 0.0)) p.fail(*p.find("scale"), "must not be negative");
  return scale;
}

// `color_space`: the pbrt colour space in effect, which an "rgb" colour is in.
LightColor light_color(const PbrtParams& p, std::string_view name, std::string_view color_space,
                       std::vector<std::string>& approximations) {
  LightColor c;
  if (auto spectrum = p.get_spectrum(name, PbrtSpectrumUse::illuminant)) {
    // Normalised to unit luminance, as pbrt-v4 normalises light spectra: `scale` is the luminance.
    set_emission_spectrum(c, std::move(*spectrum));
    c.luminance = static_cast<float>(light_scale(p));
    return c;
  }
  const PbrtColor rgb = p.get_color(name, PbrtSpectrumUse::illuminant, color_space, approximations).value_or(PbrtColor{});
  const double scale = light_scale(p);
  c.color = rgb.rgb;
  c.space = rgb.space;
  c.luminance = static_cast<float>(relative_luminance(rgb.rgb, rgb.space) * scale);
  // pbrt-v4 multiplies an rgb light by its space's illuminant, ACES' D60 for aces2065-1, and
  // films that warmer white unadapted; Prism's colour-picker rule keeps (1, 1, 1) neutral.
  if (p.has(name) && p.find(name)->type == "rgb" && color_space == "aces2065-1")
    approximations.push_back(fmt::format("'{}' (line {}) in aces2065-1 as an ACEScg colour whose white is neutral "
                                         "(pbrt-v4 emits the ACES white, D60)",
                                         name, p.find(name)->line));
  return c;
}

double optional_power(const PbrtParams& p) {
  const double power = p.get_float("power", -1.0);
  if (p.has("power") && !(power >= 0.0)) p.fail(*p.find("power"), "must not be negative");
  return power;
}

// "illuminance" in lux, when the light has one (callers check p.has first).
double illuminance_lux(const PbrtParams& p) {
  const double lux = p.get_float("illuminance", -1.0);
  if (!(lux >= 0.0)) p.fail(*p.find("illuminance"), "must not be negative");
  return lux;
}

}  // namespace

void PbrtBuilder::light_source(const std::string& type, const PbrtParams& p) {
  if (!state_.ctm.is_affine()) throw SceneError(fmt::format("{}:{}: LightSource: the transform is projective", p.source, p.line));
  const Transform t = state_.ctm.to_transform();
  Light light;
  light.name = fmt::format("{}-{}", type, p.line);
  if (type == "point" || type == "spot") {
    const LightColor c = light_color(p, "I", state_.color_space, approximations_);
    light.type = type == "point" ? LightType::point : LightType::spot;
    light.color = c.color;
    light.color_space = c.space;
    light.intensity = c.luminance;
    light.spectrum = c.spectrum;
    light.position = t.apply_point(p.get_point3("from").value_or(Vec3f(0.0f)));
    double solid_angle = 4.0 * std::numbers::pi;
    if (type == "spot") {
      const Vec3f to = t.apply_point(p.get_point3("to").value_or(Vec3f(0.0f, 0.0f, 1.0f)));
      const Vec3f axis = to - light.position;
      if (!(length(axis) > 0.0f)) throw SceneError(fmt::format("{}:{}: spot light: \"from\" equals \"to\"", p.source, p.line));
      light.direction = normalize(axis);
      const double cone = p.get_float("coneangle", 30.0), delta = p.get_float("conedelta", 5.0);
      if (!(cone > 0.0 && cone <= 180.0) || !(delta >= 0.0))
        throw SceneError(fmt::format("{}:{}: spot light: coneangle must be in (0, 180] and conedelta ≥ 0", p.source, p.line));
      light.spot_outer_angle_degrees = static_cast<float>(cone);
      light.spot_inner_angle_degrees = static_cast<float>(std::max(cone - delta, 0.0));
      // pbrt-v4's spot power normalisation: the smoothstep falloff integrates to
      // 2π (1 − (cos inner + cos outer) / 2).
      const double ci = std::cos(light.spot_inner_angle_degrees * std::numbers::pi / 180.0);
      const double co = std::cos(cone * std::numbers::pi / 180.0);
      solid_angle = 2.0 * std::numbers::pi * (1.0 - 0.5 * (ci + co));
    }
    // pbrt-v4 (PointLight/SpotLight::Create): `scale` multiplies the intensity that
    // `power` sets, and a power of 0 leaves the light as given.
    const double power = optional_power(p);
    if (power > 0.0) light.intensity = static_cast<float>(light_scale(p) * power / std::max(solid_angle, 1e-12));
  } else if (type == "distant") {
    const LightColor c = light_color(p, "L", state_.color_space, approximations_);
    light.type = LightType::directional;
    light.color = c.color;
    light.color_space = c.space;
    light.intensity = c.luminance;
    light.spectrum = c.spectrum;
    const Vec3f from = p.get_point3("from").value_or(Vec3f(0.0f));
    const Vec3f to = p.get_point3("to").value_or(Vec3f(0.0f, 0.0f, 1.0f));
    const Vec3f d = t.apply_vector(to - from);
    if (!(length(d) > 0.0f)) throw SceneError(fmt::format("{}:{}: distant light: \"from\" equals \"to\"", p.source, p.line));
    light.direction = normalize(d);
    // pbrt-v4 normalises L to unit luminance and multiplies `scale` by the illuminance.
    if (p.has("illuminance")) light.intensity = static_cast<float>(light_scale(p) * illuminance_lux(p));
  } else if (type == "infinite") {
    light.type = LightType::environment;
    const std::string file = p.get_string("filename", "");
    if (!file.empty()) {
      if (p.has("L")) throw SceneError(fmt::format("{}:{}: infinite light: give \"L\" or \"filename\", not both", p.source, p.line));
      const std::string context = fmt::format("{}:{}: infinite light", p.source, p.line);
      try {
        // pbrt-v4 reads an 8- or 16-bit PNG as sRGB-encoded (Image::Read without an
        // encoding); EXR and HDR are linear whatever is asked. Its ImageInfiniteLight keeps
        // the image's colour space (an EXR's chromaticities), as Prism's image textures do.
        light.environment_texture =
            textures_->load(resolve(p, "filename", file), TextureEncoding::srgb, TextureWrap::repeat,
                            TextureWrap::repeat, context, {}, TextureContent::color_own_gamut);
      } catch (const IoError& e) {
        throw IoError(fmt::format("{}: {}", context, e.what()));
      }
      light.intensity = static_cast<float>(light_scale(p));
      // pbrt-v4's ImageInfiniteLight looks the image up at EqualAreaSphereToSquare of the
      // direction in the light's frame (its Le(): renderFromLight⁻¹ applied to the ray
      // direction; pbrt-v4 book §12.5.2 and §3.8.3), nearest texel, pixel (0, 0) at the
      // image's top left — Prism's uv convention — and it refuses non-square images.
      light.environment_mapping = EnvironmentMapping::equal_area_octahedral;
      const TextureImage& image = textures_->image(light.environment_texture);  // its size is checked here
      if (image.width != image.height)
        throw SceneError(fmt::format("{}:{}: infinite light: \"{}\" is {}×{}; pbrt-v4's equal-area environment "
                                     "images are square",
                                     p.source, p.line, file, image.width, image.height));
      if (p.has("illuminance")) {
        // The map scaled so that a surface facing the light frame's +z receives that many
        // lux from the upper hemisphere, on top of `scale` (pbrt-v4's ImageInfiniteLight).
        const double lux = illuminance_lux(p);
        const double map_lux = environment_illuminance_lux(image, light.environment_mapping, Vec3f(0.0f, 0.0f, 1.0f));
        if (!(map_lux > 0.0))
          throw SceneError(fmt::format("{}:{}: infinite light: \"illuminance\" asks for {} lux on a surface facing +z, "
                                       "but \"{}\" sends no light into that hemisphere",
                                       p.source, p.line, lux, file));
        light.intensity = static_cast<float>(light.intensity * (lux / map_lux));
      }
    } else {
      const LightColor c = light_color(p, "L", state_.color_space, approximations_);
      light.color = c.color;
      light.color_space = c.space;
      light.intensity = c.luminance;
      light.spectrum = c.spectrum;
      // A uniform sky of luminance L gives π L lux on any surface.
      if (p.has("illuminance"))
        light.intensity = static_cast<float>(light_scale(p) * illuminance_lux(p) / std::numbers::pi);
    }
    light.environment_to_world = t;
    p.find("portal");
    for (const Light& l : scene_.lights)
      if (l.type == LightType::environment) {
        ignore("second infinite light", p);
        return;
      }
  } else {
    ignore(fmt::format("LightSource \"{}\"", type), p);
    for (const auto& param : p.params) param.used = true;
    return;
  }
  note_unused(fmt::format("LightSource \"{}\"", type), p);
  scene_.lights.push_back(std::move(light));
}

void PbrtBuilder::area_light_source(const std::string& type, const PbrtParams& p) {
  if (type != "diffuse") {
    ignore(fmt::format("AreaLightSource \"{}\"", type), p);
    for (const auto& param : p.params) param.used = true;
    return;
  }
  const LightColor c = light_color(p, "L", state_.color_space, approximations_);
  PbrtAreaLight light;
  light.color = c.color;
  light.color_space = c.space;
  light.luminance_nits = c.luminance;
  light.spectrum = c.spectrum;
  light.two_sided = p.get_bool("twosided", false);
  // pbrt-v4 (DiffuseAreaLight::Create): `scale` multiplies the radiance `power` sets; a
  // power of 0 leaves the light as given.
  const double power = optional_power(p);
  if (power > 0.0) light.power = light_scale(p) * power;
  if (p.has("filename")) ignore("AreaLightSource \"filename\"", p);
  note_unused("AreaLightSource", p);
  state_.area_light = light;
  ++area_light_id_;
}

}  // namespace prism::loaders
