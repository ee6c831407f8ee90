// prism-scene/1: materials and the textures they refer to.
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "prism/scene/dielectric_ior.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/json_scene_reader.h"
#include "prism/scene/loaders/path_safety.h"
#include "prism/scene/spectral_inputs.h"

namespace prism::loaders {
namespace {

// Sellmeier coefficients (B1, B2, B3, C1, C2, C3 with C in µm²) of the glasses a scene may
// name, from the SCHOTT (N-BK7) and Malitson 1965 (fused silica) fits; see data/SOURCES.md.
struct NamedGlass {
  std::string_view name;
  std::array<float, 6> sellmeier;
};
constexpr NamedGlass kGlasses[] = {
    {"N-BK7", {1.03961212f, 0.231792344f, 1.01046945f, 0.00600069867f, 0.0200179144f, 103.560653f}},
    {"fused-silica", {0.6961663f, 0.4079426f, 0.8974794f, 0.00467914825849f, 0.01351206307396f, 97.934002537921f}},
};

// Index of refraction at the helium d line (587.56 nm), the usual n_d.
float ior_at_d_line(DispersionModel model, const std::array<float, 6>& c) {
  const double l2 = 0.58756 * 0.58756;  // µm²
  if (model == DispersionModel::cauchy) return static_cast<float>(c[0] + c[1] / l2);
  double n2 = 1.0;
  for (int i = 0; i < 3; ++i) n2 += c[i] * l2 / (l2 - c[3 + i]);
  return static_cast<float>(std::sqrt(std::max(n2, 1.0)));
}

void read_dispersion(Material& m, const JsonValue& value) {
  if (value.is_string()) {
    const std::string name = value.as_string();
    for (const auto& glass : kGlasses)
      if (glass.name == name) {
        m.dispersion = DispersionModel::sellmeier;
        m.dispersion_coefficients = glass.sellmeier;
        m.ior = ior_at_d_line(m.dispersion, m.dispersion_coefficients);
        return;
      }
    value.fail(fmt::format("unknown glass '{}' (known: N-BK7, fused-silica)", name));
  }
  if (value.has("abbe_number")) {
    // A glass by its d-line index and Abbe number: the two-term Cauchy glass of
    // KHR_materials_dispersion (bsdf::CauchyIor::from_abbe_number).
    value.expect_keys({"n_d", "abbe_number"});
    const float n_d = value["n_d"].as_float(1.0f, 10.0f);
    const float abbe_number = value["abbe_number"].as_float(1.0f, 1e6f);
    set_cauchy_dispersion(m, bsdf::CauchyIor::from_abbe_number(n_d, abbe_number));
    m.ior = n_d;
    return;
  }
  value.expect_keys({"model", "coefficients"});
  m.dispersion = value["model"].as_enum<DispersionModel>(
      {{"none", DispersionModel::none}, {"cauchy", DispersionModel::cauchy}, {"sellmeier", DispersionModel::sellmeier}});
  if (m.dispersion == DispersionModel::none) return;
  const std::size_t count = m.dispersion == DispersionModel::cauchy ? 2 : 6;
  const JsonValue coefficients = value["coefficients"];
  const auto c = coefficients.elements(count);
  if (c.size() != count) coefficients.fail(fmt::format("expected {} coefficients", count));
  m.dispersion_coefficients = {};
  for (std::size_t i = 0; i < count; ++i) m.dispersion_coefficients[i] = c[i].as_float(-1e6f, 1e6f);
  m.ior = ior_at_d_line(m.dispersion, m.dispersion_coefficients);
  if (!(m.ior >= 1.0f && m.ior < 10.0f)) coefficients.fail(fmt::format("gives n_d = {}, outside [1, 10)", m.ior));
}

void read_emission(JsonSceneReader& reader, Material& m, std::uint32_t index, const JsonValue& value) {
  value.expect_keys({"color", "color_space", "spectrum", "luminance_nits", "power_lm", "two_sided", "texture"});
  Emission& e = m.emission;
  e.color = value.get_vec3("color", Vec3f(1.0f));
  if (min(e.color, Vec3f(0.0f)) != Vec3f(0.0f)) value["color"].fail("colour components must not be negative");
  if (auto s = value.find("color_space")) e.color_space = read_color_picker_space(*s);
  if (auto s = value.find("spectrum")) {
    if (value.has("color") || value.has("color_space")) value.fail("give either 'color' or 'spectrum', not both");
    if (value.has("texture")) value.fail("an emission texture multiplies a colour: it cannot go with 'spectrum'");
    set_emission_spectrum(e, reader.read_spectrum(*s, SpectrumUse::emission));
  }
  e.two_sided = value.get_bool("two_sided", false);
  if (value.has("luminance_nits") == value.has("power_lm"))
    value.fail("give exactly one of 'luminance_nits' and 'power_lm'");
  if (auto l = value.find("luminance_nits")) e.luminance_nits = l->as_float(0.0f, 1e12f);
  if (auto p = value.find("power_lm")) reader.emission_power_lm[index] = p->as_float(0.0f, 1e15f);
  // An OpenEXR texture is read into the colour's space (as a wide-gamut base colour's is).
  if (auto t = value.find("texture"))
    e.texture = reader.read_texture(*t, TextureEncoding::srgb, {}, color_content_in(e.color_space));
}

}  // namespace

ColorPickerSpace read_color_picker_space(const JsonValue& value) {
  return value.as_enum<ColorPickerSpace>(
      {{"srgb", ColorPickerSpace::srgb}, {"acescg", ColorPickerSpace::acescg}, {"rec2020", ColorPickerSpace::rec2020}});
}

std::filesystem::path JsonSceneReader::resolve(const JsonValue& file_name) const {
  return resolve_scene_reference(scene_dir, file_name.as_string(), options.allow_external_paths,
                                 fmt::format("{}: {}", document.source, file_name.path()));
}

int JsonSceneReader::read_texture(const JsonValue& value, TextureEncoding default_encoding,
                                  TextureCache::ImageCheck check, TextureContent colour_content) {
  // What the key reads is colour or data whatever encoding the file is given in.
  const TextureContent content = default_encoding == TextureEncoding::srgb ? colour_content : TextureContent::data;
  if (value.is_string())
    return textures.load(resolve(value), default_encoding, TextureWrap::repeat, TextureWrap::repeat, {},
                         std::move(check), content);
  value.expect_keys({"file", "encoding", "wrap", "wrap_u", "wrap_v"});
  const auto wrap_mode = [](const JsonValue& w) {
    return w.as_enum(kTextureWrapNames);
  };
  TextureWrap wrap_u = TextureWrap::repeat, wrap_v = TextureWrap::repeat;
  if (auto w = value.find("wrap")) wrap_u = wrap_v = wrap_mode(*w);
  if (auto w = value.find("wrap_u")) wrap_u = wrap_mode(*w);
  if (auto w = value.find("wrap_v")) wrap_v = wrap_mode(*w);
  TextureEncoding encoding = default_encoding;
  if (auto e = value.find("encoding"))
    encoding = e->as_enum<TextureEncoding>({{"srgb", TextureEncoding::srgb}, {"linear", TextureEncoding::linear}});
  return textures.load(resolve(value["file"]), encoding, wrap_u, wrap_v, {}, std::move(check), content);
}

std::uint32_t JsonSceneReader::material_index(const JsonValue& name) const {
  const std::string n = name.as_string();
  const auto it = material_indices.find(n);
  if (it == material_indices.end()) name.fail(fmt::format("no material named '{}'", n));
  return it->second;
}

// Absorption inside solid glass (glTF KHR_materials_volume's attenuationColor and
// attenuationDistance; render/volume_absorption.h). Only where a path can be inside: a
// dielectric (after transmission made one) that is not thin-walled.
void JsonSceneReader::read_attenuation(Material& m, const JsonValue& value) const {
  const auto color = value.find("attenuation_color");
  const auto distance = value.find("attenuation_distance");
  if (!color && !distance) return;
  const JsonValue& where = color ? *color : *distance;
  if (m.type != MaterialType::dielectric)
    where.fail("only dielectric materials (and transmitting metallic_roughness ones) have an inside to absorb in");
  if (m.thin_walled) where.fail("a thin-walled dielectric has no inside to absorb in");
  // Either alone would change nothing (glTF's defaults are white and an infinite distance).
  if (!color || !distance) value.fail("give 'attenuation_color' and 'attenuation_distance' together");
  m.attenuation_color = color->as_vec3();
  if (!(min_component(m.attenuation_color) > 0.0f && max_component(m.attenuation_color) <= 1.0f))
    color->fail("components must be in (0, 1]: the share of light left after attenuation_distance");
  m.attenuation_distance = distance->as_float(0.0f, std::numeric_limits<float>::max());
  if (!(m.attenuation_distance > 0.0f)) distance->fail("must be greater than 0 (scene units)");
}

// A clear coat (glTF KHR_materials_clearcoat; bsdf/clearcoat.h) over any material but glass.
void JsonSceneReader::read_clearcoat(Material& m, const JsonValue& value) {
  const auto weight = value.find("clearcoat");
  if (!weight) {
    for (const char* key : {"clearcoat_roughness", "clearcoat_texture", "clearcoat_roughness_texture",
                            "clearcoat_normal_texture", "clearcoat_normal_scale"})
      if (value.has(key)) value[key].fail("give 'clearcoat' (the coat's weight in [0, 1]) with it");
    return;
  }
  if (m.type == MaterialType::dielectric)
    weight->fail("a dielectric takes no clear coat (coats go on diffuse, mirror, conductor and metallic_roughness)");
  m.clearcoat = weight->as_float(0.0f, 1.0f);
  m.clearcoat_roughness = value.get_float("clearcoat_roughness", m.clearcoat_roughness, 0.0f, 1.0f);
  // glTF's channels: R of the weight texture, G of the roughness texture (both linear).
  if (auto t = value.find("clearcoat_texture")) m.clearcoat_texture = read_texture(*t, TextureEncoding::linear);
  if (auto t = value.find("clearcoat_roughness_texture"))
    m.clearcoat_roughness_texture = read_texture(*t, TextureEncoding::linear);
  // The coat's own normal map, as normal_texture is the base's.
  if (auto t = value.find("clearcoat_normal_texture")) {
    m.clearcoat_normal_texture = read_texture(*t, TextureEncoding::linear, [where = *t](const TextureImage& image) {
      if (image.channels < 3) where.fail("a normal map needs an RGB image (tangent-space x, y, z)");
    });
  }
  m.clearcoat_normal_scale = value.get_float("clearcoat_normal_scale", m.clearcoat_normal_scale, -100.0f, 100.0f);
}

// A sheen (glTF KHR_materials_sheen; bsdf/sheen.h) over any material but glass.
void JsonSceneReader::read_sheen(Material& m, const JsonValue& value) {
  const auto color = value.find("sheen_color");
  if (!color) {
    for (const char* key : {"sheen_roughness", "sheen_color_texture", "sheen_roughness_texture"})
      if (value.has(key)) value[key].fail("give 'sheen_color' (the sheen's linear Rec.709 colour) with it");
    return;
  }
  if (m.type == MaterialType::dielectric)
    color->fail("a dielectric takes no sheen (sheens go on diffuse, mirror, conductor and metallic_roughness)");
  m.sheen_color = value.get_vec3("sheen_color", m.sheen_color);
  if (!(min_component(m.sheen_color) >= 0.0f && max_component(m.sheen_color) <= 1.0f))
    color->fail("sheen colour components must be in [0, 1]");
  m.sheen_roughness = value.get_float("sheen_roughness", m.sheen_roughness, 0.0f, 1.0f);
  // glTF's encodings: the colour texture sRGB-encoded, the roughness in A, linear.
  if (auto t = value.find("sheen_color_texture")) m.sheen_color_texture = read_texture(*t, TextureEncoding::srgb);
  if (auto t = value.find("sheen_roughness_texture"))
    m.sheen_roughness_texture = read_texture(*t, TextureEncoding::linear);
}

// A thin film (glTF KHR_materials_iridescence; bsdf/thin_film.h) on a metallic_roughness
// material.
void JsonSceneReader::read_iridescence(Material& m, const JsonValue& value) {
  const auto weight = value.find("iridescence");
  if (!weight) {
    for (const char* key : {"iridescence_ior", "iridescence_thickness_min_nm", "iridescence_thickness_max_nm",
                            "iridescence_texture", "iridescence_thickness_texture"})
      if (value.has(key)) value[key].fail("give 'iridescence' (the thin film's weight) with it");
    return;
  }
  if (m.type != MaterialType::metallic_roughness)
    weight->fail("only metallic_roughness materials take a thin film");
  m.iridescence = value.get_float("iridescence", m.iridescence, 0.0f, 1.0f);
  m.iridescence_ior = value.get_float("iridescence_ior", m.iridescence_ior, 1.0f, 10.0f);
  m.iridescence_thickness_min_nm =
      value.get_float("iridescence_thickness_min_nm", m.iridescence_thickness_min_nm, 0.0f, 1e5f);
  m.iridescence_thickness_max_nm =
      value.get_float("iridescence_thickness_max_nm", m.iridescence_thickness_max_nm, 0.0f, 1e5f);
  // glTF's encodings: both linear, the weight in R, the thickness in G.
  if (auto t = value.find("iridescence_texture")) m.iridescence_texture = read_texture(*t, TextureEncoding::linear);
  if (auto t = value.find("iridescence_thickness_texture"))
    m.iridescence_thickness_texture = read_texture(*t, TextureEncoding::linear);
}

void JsonSceneReader::read_material(const JsonValue& value) {
  value.expect_keys({"name", "type", "base_color", "base_color_space", "base_color_spectrum", "base_color_texture", "roughness",
                     "anisotropy", "anisotropy_rotation_degrees", "anisotropy_texture", "metallic", "metallic_roughness_texture", "normal_texture", "normal_scale",
                     "bump_texture", "bump_scale", "microfacet", "conductor", "ior", "dispersion", "thin_walled",
                     "transmission", "attenuation_color", "attenuation_distance", "specular", "specular_color",
                     "specular_texture", "specular_color_texture", "clearcoat", "clearcoat_roughness",
                     "clearcoat_texture", "clearcoat_roughness_texture", "clearcoat_normal_texture",
                     "clearcoat_normal_scale", "sheen_color", "sheen_roughness",
                     "sheen_color_texture", "sheen_roughness_texture", "iridescence", "iridescence_ior",
                     "iridescence_thickness_min_nm", "iridescence_thickness_max_nm", "iridescence_texture",
                     "iridescence_thickness_texture", "alpha_mode", "alpha_cutoff", "opacity",
                     "emission"});
  Material m;
  m.name = value["name"].as_string();
  if (material_indices.contains(m.name)) value["name"].fail(fmt::format("material '{}' is defined twice", m.name));
  m.type = value["type"].as_enum(kMaterialTypeNames);
  // Glass is untinted unless a colour is given (the 0.8 albedo default would darken it).
  m.base_color = value.get_vec3("base_color", m.type == MaterialType::dielectric ? Vec3f(1.0f) : m.base_color);
  if (min(m.base_color, Vec3f(0.0f)) != Vec3f(0.0f)) value["base_color"].fail("colour components must not be negative");
  if (auto s = value.find("base_color_space")) m.base_color_space = read_color_picker_space(*s);
  if (auto t = value.find("base_color_texture"))
    m.base_color_texture = read_texture(*t, TextureEncoding::srgb, {}, color_content_in(m.base_color_space));
  if (auto s = value.find("base_color_spectrum")) {
    if (value.has("base_color_space")) value.fail("give either 'base_color_space' or 'base_color_spectrum', not both");
    if (value.has("base_color")) value.fail("give either 'base_color' or 'base_color_spectrum', not both");
    if (value.has("base_color_texture"))
      value.fail("a base colour texture multiplies a colour: it cannot go with 'base_color_spectrum'");
    set_base_color_spectrum(m, read_spectrum(*s, SpectrumUse::reflectance));
  }
  m.roughness = value.get_float("roughness", m.roughness, 0.0f, 1.0f);
  // glTF KHR_materials_anisotropy's strength, rotation (here in degrees) and texture (linear:
  // RG direction, B strength).
  m.anisotropy = value.get_float("anisotropy", m.anisotropy, 0.0f, 1.0f);
  m.anisotropy_rotation_rad = static_cast<float>(
      value.get_float("anisotropy_rotation_degrees", 0.0f, -360.0f, 360.0f) * std::numbers::pi / 180.0);
  if (auto t = value.find("anisotropy_texture")) m.anisotropy_texture = read_texture(*t, TextureEncoding::linear);
  m.metallic = value.get_float("metallic", m.metallic, 0.0f, 1.0f);
  if (auto t = value.find("metallic_roughness_texture"))
    m.metallic_roughness_texture = read_texture(*t, TextureEncoding::linear);
  if (auto t = value.find("normal_texture")) {
    // Checked once decoded, with the scene's other images (texture_cache.h).
    m.normal_texture = read_texture(*t, TextureEncoding::linear, [where = *t](const TextureImage& image) {
      if (image.channels < 3) where.fail("a normal map needs an RGB image (tangent-space x, y, z)");
    });
  }
  m.normal_scale = value.get_float("normal_scale", m.normal_scale, -100.0f, 100.0f);
  if (auto t = value.find("bump_texture")) m.bump_texture = read_texture(*t, TextureEncoding::linear);
  m.bump_scale = value.get_float("bump_scale", m.bump_scale, -1e6f, 1e6f);
  if (auto mf = value.find("microfacet")) {
    m.microfacet = mf->as_enum<MicrofacetModel>(
        {{"ggx", MicrofacetModel::ggx}, {"beckmann", MicrofacetModel::beckmann}, {"blinn_phong", MicrofacetModel::blinn_phong}});
    // Only conductors and glass take a distribution; glTF's metallic-roughness model is GGX.
    if (m.microfacet != MicrofacetModel::ggx && m.type != MaterialType::conductor && m.type != MaterialType::dielectric)
      mf->fail("only conductor and dielectric materials take another distribution than ggx");
  }
  if (auto c = value.find("conductor")) {
    m.conductor_name = c->as_string();
    if (m.conductor_name != "Au" && m.conductor_name != "Ag" && m.conductor_name != "Cu" && m.conductor_name != "Al")
      c->fail(fmt::format("unknown conductor '{}' (known: Au, Ag, Cu, Al)", m.conductor_name));
    m.conductor_fresnel = ConductorFresnel::complex_ior;
  }
  m.ior = value.get_float("ior", m.ior, 1.0f, 10.0f);
  if (auto d = value.find("dispersion")) {
    if (value.has("ior")) value.fail("give either 'ior' or 'dispersion', not both");
    read_dispersion(m, *d);
  }
  m.thin_walled = value.get_bool("thin_walled", m.thin_walled);
  if (auto t = value.find("transmission")) {
    // glTF's rule (KHR_materials_transmission, as the glTF reader applies it): a
    // transmitting metallic-roughness material is glass tinted by its base colour.
    m.transmission = t->as_float(0.0f, 1.0f);
    if (m.transmission > 0.0f && m.type == MaterialType::metallic_roughness) {
      m.type = MaterialType::dielectric;
      if (!value.has("base_color") && !m.base_color_spectrum) m.base_color = Vec3f(1.0f);  // as for glass
      if (m.transmission < 1.0f || m.metallic > 0.0f)
        scene.warnings.push_back(fmt::format("{}: {}: partial transmission/metallic mixed into a dielectric",
                                             document.source, t->path()));
    } else if (m.transmission > 0.0f && m.type != MaterialType::dielectric) {
      t->fail("only metallic_roughness (glTF's transmission) and dielectric materials transmit");
    }
  }
  read_attenuation(m, value);
  // KHR_materials_specular's factors, on metallic_roughness (after transmission, which
  // makes glass of it, has had its say).
  for (const char* key : {"specular", "specular_color", "specular_texture", "specular_color_texture"})
    if (value.has(key) && m.type != MaterialType::metallic_roughness)
      value[key].fail("only metallic_roughness materials have a dielectric specular layer to weight");
  m.specular = value.get_float("specular", m.specular, 0.0f, 1.0f);
  m.specular_color = value.get_vec3("specular_color", m.specular_color);
  if (!(min_component(m.specular_color) >= 0.0f)) value["specular_color"].fail("colour components must not be negative");
  // glTF's encodings: the weight in A, linear; the colour texture sRGB-encoded.
  if (auto t = value.find("specular_texture")) m.specular_texture = read_texture(*t, TextureEncoding::linear);
  if (auto t = value.find("specular_color_texture")) m.specular_color_texture = read_texture(*t, TextureEncoding::srgb);
  read_clearcoat(m, value);
  read_sheen(m, value);
  read_iridescence(m, value);
  if (auto a = value.find("alpha_mode"))
    m.alpha_mode = a->as_enum(kAlphaModeNames);
  m.alpha_cutoff = value.get_float("alpha_cutoff", m.alpha_cutoff, 0.0f, 1.0f);
  m.opacity = value.get_float("opacity", m.opacity, 0.0f, 1.0f);
  const auto index = static_cast<std::uint32_t>(scene.materials.size());
  if (auto e = value.find("emission")) read_emission(*this, m, index, *e);
  material_indices.emplace(m.name, index);
  scene.materials.push_back(std::move(m));
}

}  // namespace prism::loaders
