// pbrt-v4 materials and textures → Prism materials (mapping in docs/scene-formats.md).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "prism/bsdf/ior.h"
#include "prism/bsdf/microfacet.h"
#include "prism/core/error.h"
#include "prism/scene/dielectric_ior.h"
#include "prism/scene/loaders/pbrt_builder.h"
#include "prism/scene/spectral_inputs.h"

namespace prism::loaders {
namespace {

// pbrt's roughness parameter → Prism's perceptual roughness r (α = r²). With
// remaproughness pbrt uses α = sqrt(roughness); without it α = roughness.
float prism_roughness(double pbrt_roughness, bool remap) {
  const double alpha = remap ? std::sqrt(pbrt_roughness) : pbrt_roughness;
  return static_cast<float>(std::sqrt(std::clamp(alpha, 0.0, 1.0)));
}

// "metal-Au-eta" → "Au" when it names a metal Prism has tables for.
std::string metal_name(const std::string& spectrum) {
  for (const char* metal : {"Au", "Ag", "Cu", "Al"})
    if (spectrum == fmt::format("metal-{}-eta", metal) || spectrum == fmt::format("metal-{}-k", metal)) return metal;
  return {};
}

// A layer's roughness as Prism's perceptual r: a number, or 1 times a texture; with
// different uroughness and vroughness numbers, r across the rougher direction and the
// anisotropy that stretches it (render/anisotropy.h): along dP/du (rotation 0) where
// uroughness is the larger, along the bitangent (rotation π/2) where vroughness is.
struct LayerRoughness {
  float value = 0.0f;
  int texture = -1;
  float anisotropy = 0.0f;
  float anisotropy_rotation_rad = 0.0f;
};

// pbrt-v4's float texture of roughness (its channel 0 times `scale`, pbrt's value before
// remapping) as a Prism roughness texture: a copy of the image holding r = prism_roughness()
// per texel (the map is not linear, so it cannot stay a scale) in its G channel, which
// metallic_roughness_texture and clearcoat_roughness_texture read, and B = 1, so that the
// metallic factor it also multiplies is kept.
int bake_roughness_texture(TextureCache& cache, Scene& scene, int image, float scale, bool remap) {
  const int copy = cache.add_with_uv_transform(image, 1.0, 1.0, 0.0, 0.0);  // decoded, same addressing
  TextureImage& t = scene.textures[static_cast<std::size_t>(copy)];
  const std::vector<float> values = t.linear_values();
  const auto channels = static_cast<std::size_t>(t.channels);
  const std::size_t texels = values.size() / channels;
  std::vector<float> rgb(texels * 3);
  for (std::size_t k = 0; k < texels; ++k) {
    const float r = prism_roughness(std::max(0.0f, scale * values[k * channels]), remap);
    rgb[3 * k] = rgb[3 * k + 1] = r;
    rgb[3 * k + 2] = 1.0f;
  }
  t.texels = std::move(rgb);
  t.channels = 3;
  t.codes = {};
  t.rgbe = {};
  t.halves = {};
  t.encoding = TextureEncoding::linear;
  t.name += " (roughness)";
  return copy;
}

const std::string* named_spectrum(const PbrtParams& p, std::string_view name) {
  const PbrtParam* param = p.find(name);
  if (!param || param->type != "spectrum" || param->strings.size() != 1) return nullptr;
  return &param->strings[0];
}

// A dielectric's "spectrum eta" given as (λ, η) pairs: the Cauchy glass closest to them
// (bsdf::fit_cauchy), which is what Prism's dielectrics refract with. Pairs a Cauchy glass
// misses by more than 0.001 somewhere (a Sellmeier glass across the whole visible does
// not; an index error of 0.001 moves a refracted ray by under 0.1°) are said to be
// approximated.
std::optional<std::string> read_sampled_eta(Material& m, const PbrtParams& p, const PbrtParam& eta) {
  const auto& v = eta.numbers;
  if (v.size() < 2 || v.size() % 2 != 0) p.fail(eta, "expected (wavelength, index) pairs");
  std::vector<double> nm, n;
  for (std::size_t i = 0; i < v.size(); i += 2) {
    if (!(v[i] > 0.0 && v[i] < 1e5) || (!nm.empty() && !(v[i] > nm.back())))
      p.fail(eta, "wavelengths must be positive and increasing");
    if (!(v[i + 1] >= 1.0 && v[i + 1] <= 10.0)) p.fail(eta, "indices must be between 1 and 10");
    nm.push_back(v[i]);
    n.push_back(v[i + 1]);
  }
  const bsdf::CauchyFit fit = bsdf::fit_cauchy(nm, n);
  m.ior = static_cast<float>(fit.ior(bsdf::kFraunhoferD_nm));
  if (fit.ior.b_um2 != 0.0) set_cauchy_dispersion(m, fit.ior);
  constexpr double kIndexTolerance = 1e-3;
  if (fit.max_residual <= kIndexTolerance) return std::nullopt;
  return fmt::format("dielectric (line {}) sampled eta as the Cauchy glass closest to it (index off by up to {:.4f})",
                     p.line, fit.max_residual);
}

}  // namespace

std::optional<PbrtColor> PbrtBuilder::reflectance(const PbrtParams& p, std::string_view name, int& texture) {
  const PbrtParam* param = p.find(name);
  if (!param) return std::nullopt;
  if (param->type == "texture") {
    const std::string tex = p.get_string(name, "");
    const auto it = named_textures_.find(tex);
    if (it == named_textures_.end()) p.fail(*param, fmt::format("unknown texture '{}'", tex));
    texture = it->second.image;
    return PbrtColor{it->second.value, it->second.space};
  }
  return p.get_color(name, PbrtSpectrumUse::reflectance, state_.color_space, approximations_);
}

void PbrtBuilder::make_material(const std::string& type, const PbrtParams& p, const std::string& name) {
  Material m;
  m.name = name.empty() ? fmt::format("{}-{}", type, p.line) : name;
  const bool remap = p.get_bool("remaproughness", true);
  // A layer's roughness: pbrt-v4's uroughness and vroughness, each defaulting to roughness
  // (default 0). `prefix` names the layer: "" or coatedconductor's "interface." / "conductor.".
  // `anisotropic`: the layer can be anisotropic (a conductor's or a dielectric's base; the
  // coat is isotropic and takes the mean).
  const auto roughness = [&](const std::string& prefix = "", bool anisotropic = false) -> LayerRoughness {
    const PbrtParam* base = p.find(prefix + "roughness");
    const PbrtParam* u = p.has(prefix + "uroughness") ? p.find(prefix + "uroughness") : base;
    const PbrtParam* v = p.has(prefix + "vroughness") ? p.find(prefix + "vroughness") : base;
    const auto is_texture = [](const PbrtParam* q) { return q && q->type == "texture"; };
    if (is_texture(u) || is_texture(v)) {
      const PbrtParam* t = is_texture(u) ? u : v;
      const PbrtParam* other = t == u ? v : u;
      if (other != t && !(is_texture(other) && other->strings == t->strings))
        approximations_.push_back(
            fmt::format("Material line {}: anisotropic roughness as its {} texture", p.line, t->name));
      const std::string name = p.get_string(t->name, "");
      const auto it = float_textures_.find(name);
      if (it == float_textures_.end()) p.fail(*t, fmt::format("unknown float texture '{}'", name));
      const PbrtTexture& texture = it->second;
      if (texture.image < 0) return {prism_roughness(std::max(0.0f, texture.value.x), remap), -1};
      return {1.0f, bake_roughness_texture(*textures_, scene_, texture.image, texture.value.x, remap)};
    }
    const auto value = [&](const PbrtParam* q) { return q ? p.get_float(q->name, 0.0) : 0.0; };
    const double ur = value(u), vr = value(v);
    if (ur < 0 || vr < 0) throw SceneError(fmt::format("{}:{}: roughness must not be negative", p.source, p.line));
    if (ur != vr && anisotropic) {
      // α = r² per direction; the narrower lobe sets α across, and at least
      // kMinAnisotropicAlpha as the renderer holds it.
      const auto alpha = [&](double pbrt) {
        const float r = prism_roughness(pbrt, remap);
        return r * r;
      };
      const float alpha_u = alpha(ur), alpha_v = alpha(vr);
      const float across = std::max(std::min(alpha_u, alpha_v), bsdf::kMinAnisotropicAlpha);
      return {std::sqrt(across), -1, bsdf::anisotropy_strength_for(across, std::max(alpha_u, alpha_v)),
              alpha_u >= alpha_v ? 0.0f : static_cast<float>(std::numbers::pi / 2)};
    }
    if (ur != vr) approximations_.push_back(fmt::format("Material line {}: anisotropic roughness as its mean", p.line));
    return {prism_roughness(0.5 * (ur + vr), remap), -1};
  };
  std::string effective = type;
  std::string conductor_prefix;  // coatedconductor's base: "conductor.eta", "conductor.roughness", ...
  if (type == "coateddiffuse" || type == "coatedconductor") {
    // pbrt-v4 coats with a dielectric interface over a thin medium and walks light between
    // the two layers at random; Prism's clear coat (bsdf/clearcoat.h) is the glTF layering
    // of an η = 1.5 GGX interface over the base, with no medium in between.
    const std::string interface = type == "coateddiffuse" ? "" : "interface.";
    m.clearcoat = 1.0f;
    const LayerRoughness coat = roughness(interface);
    m.clearcoat_roughness = coat.value;
    m.clearcoat_roughness_texture = coat.texture;
    // pbrt-v4 takes a number or a spectrum (a named glass) for the interface's η.
    std::string dropped;
    if (const PbrtParam* eta_param = p.find(interface + "eta"); eta_param && eta_param->type == "spectrum") {
      dropped = fmt::format(", {}eta spectrum as 1.5", interface);
    } else {
      const double eta = p.get_float(interface + "eta", 1.5);
      if (!(eta > 0.0) || eta > 10.0) p.fail(*eta_param, "must be between 0 and 10");
      if (eta != 1.5) dropped = fmt::format(", {}eta {} as 1.5", interface, eta);
    }
    if (p.has("albedo")) dropped += ", the coat's albedo (no medium between the layers)";
    approximations_.push_back(fmt::format("Material \"{}\" (line {}) as a clear coat over a {} base{}", type, p.line,
                                          type == "coateddiffuse" ? "diffuse" : "conductor", dropped));
    for (const char* n : {"thickness", "albedo", "g", "maxdepth", "nsamples"}) p.find(n);
    effective = type == "coateddiffuse" ? "diffuse" : "conductor";
    if (type == "coatedconductor") conductor_prefix = "conductor.";
  } else if (type == "diffusetransmission" || type == "subsurface") {
    approximations_.push_back(fmt::format("Material \"{}\" (line {}) as diffuse", type, p.line));
    effective = "diffuse";
  } else if (type == "thindielectric") {
    m.thin_walled = true;
    effective = "dielectric";
  }
  if (effective == "diffuse") {
    m.type = MaterialType::diffuse;
    if (auto measured = p.get_spectrum("reflectance", PbrtSpectrumUse::reflectance)) {
      set_base_color_spectrum(m, std::move(*measured));  // rendered as data
    } else {
      const PbrtColor c = reflectance(p, "reflectance", m.base_color_texture).value_or(PbrtColor{Vec3f(0.5f)});
      m.base_color = c.rgb;
      m.base_color_space = c.space;
    }
    if (type != "diffuse")
      for (const char* n : {"roughness", "thickness", "albedo", "g"}) p.find(n);
  } else if (effective == "conductor") {
    m.type = MaterialType::conductor;
    const LayerRoughness r = roughness(conductor_prefix, true);
    m.roughness = r.value;
    m.metallic_roughness_texture = r.texture;
    m.anisotropy = r.anisotropy;
    m.anisotropy_rotation_rad = r.anisotropy_rotation_rad;
    if (auto r = reflectance(p, "reflectance", m.base_color_texture)) {
      m.conductor_fresnel = ConductorFresnel::schlick;
      m.base_color = r->rgb;
      m.base_color_space = r->space;
    } else {
      const std::string eta_name = conductor_prefix + "eta", k_name = conductor_prefix + "k";
      const std::string* eta = named_spectrum(p, eta_name);
      const std::string* k = named_spectrum(p, k_name);
      std::string metal = eta ? metal_name(*eta) : "Cu";
      if (k && metal_name(*k) != metal) metal.clear();
      if ((p.has(eta_name) && !eta) || (p.has(k_name) && !k) || metal.empty()) {
        approximations_.push_back(fmt::format("conductor (line {}) eta/k not a named metal of Au/Ag/Cu/Al: copper used", p.line));
        metal = "Cu";
      }
      m.conductor_fresnel = ConductorFresnel::complex_ior;
      m.conductor_name = metal;
      m.base_color = Vec3f(1.0f);
    }
  } else if (effective == "dielectric") {
    m.type = MaterialType::dielectric;
    const LayerRoughness r = roughness("", !m.thin_walled);  // thindielectric is smooth
    m.roughness = r.value;
    m.metallic_roughness_texture = r.texture;
    m.anisotropy = r.anisotropy;
    m.anisotropy_rotation_rad = r.anisotropy_rotation_rad;
    m.base_color = Vec3f(1.0f);
    if (const std::string* eta = named_spectrum(p, "eta")) {
      if (*eta == "glass-BK7") {
        const bsdf::SellmeierIor bk7 = bsdf::sellmeier_bk7();
        m.dispersion = DispersionModel::sellmeier;
        for (int i = 0; i < 3; ++i) {
          m.dispersion_coefficients[i] = static_cast<float>(bk7.b[i]);
          m.dispersion_coefficients[3 + i] = static_cast<float>(bk7.c_um2[i]);
        }
        m.ior = static_cast<float>(bk7(587.56));
      } else {
        approximations_.push_back(fmt::format("dielectric (line {}) eta \"{}\" as 1.5", p.line, *eta));
        m.ior = 1.5f;
      }
    } else if (const PbrtParam* sampled = p.find("eta"); sampled && sampled->type == "spectrum") {
      if (auto note = read_sampled_eta(m, p, *sampled)) approximations_.push_back(std::move(*note));
    } else {
      const double eta_value = p.get_float("eta", 1.5);
      if (!(eta_value > 0.0) || eta_value > 10.0) p.fail(*p.find("eta"), "must be between 0 and 10");
      m.ior = static_cast<float>(eta_value);
    }
  } else if (type == "interface") {
    ignore("Material \"interface\" (treated as diffuse)", p);
    m.base_color = Vec3f(0.5f);
  } else {
    ignore(fmt::format("Material \"{}\" (treated as diffuse 0.5)", type), p);
    m.base_color = Vec3f(0.5f);
    for (const auto& param : p.params) param.used = true;
  }
  // pbrt-v4's "normalmap": an RGB image read as linear, repeated, in the frame (dP/du,
  // n × dP/du, n), whose y runs up the image as glTF's does (normal_mapping.h).
  if (const std::string normal_map = p.get_string("normalmap", ""); !normal_map.empty()) {
    // Decoded with the scene's other images (texture_cache.h), then checked.
    const std::string context = fmt::format("{}:{}: Material normalmap", p.source, p.line);
    const std::string not_rgb = fmt::format("{}:{}: parameter 'normalmap': a normal map needs an RGB image", p.source,
                                            p.find("normalmap")->line);
    const auto check = [not_rgb](const TextureImage& image) {
      if (image.channels < 3) throw SceneError(not_rgb);
    };
    try {
      m.normal_texture = textures_->load(resolve(p, "normalmap", normal_map), TextureEncoding::linear,
                                         TextureWrap::repeat, TextureWrap::repeat, context, check);
    } catch (const IoError& e) {
      throw IoError(fmt::format("{}: {}", context, e.what()));
    }
  }
  // "texture displacement": a float texture as a bump map (pbrt-v4's BumpMap), its image's
  // values times the texture's "scale" in scene units. A constant displacement moves the
  // surface without bending it: nothing to do.
  if (const PbrtParam* displacement = p.find("displacement"); displacement && displacement->type != "float") {
    if (displacement->type != "texture") p.fail(*displacement, "expected a float texture or a float");
    const std::string tex = p.get_string("displacement", "");
    const auto it = float_textures_.find(tex);
    if (it == float_textures_.end()) p.fail(*displacement, fmt::format("unknown float texture '{}'", tex));
    m.bump_texture = it->second.image;
    m.bump_scale = it->second.value.x;
  }
  note_unused(fmt::format("Material \"{}\"", type), p);
  scene_.materials.push_back(std::move(m));
  const int index = static_cast<int>(scene_.materials.size() - 1);
  if (name.empty()) {
    state_.material = index;
  } else {
    named_materials_[name] = index;
  }
}

PbrtTexture PbrtBuilder::imagemap(const std::string& name, const PbrtParams& p, bool is_float) {
  PbrtTexture t;
  const std::string file = p.get_string("filename", "");
  if (file.empty()) throw SceneError(fmt::format("{}:{}: Texture '{}': imagemap needs a filename", p.source, p.line, name));
  const std::string encoding = p.get_string("encoding", "sRGB");
  const std::string wrap = p.get_string("wrap", "repeat");
  TextureWrap w = TextureWrap::repeat;
  if (wrap == "clamp" || wrap == "black") w = TextureWrap::clamp;
  else if (wrap == "octahedralsphere") w = TextureWrap::mirror;
  else if (wrap != "repeat") p.fail(*p.find("wrap"), "expected repeat, clamp, black or octahedralsphere");
  if (wrap == "black") approximations_.push_back(fmt::format("Texture '{}' wrap \"black\" as clamp", name));
  const TextureEncoding enc = encoding == "linear" ? TextureEncoding::linear : TextureEncoding::srgb;
  if (encoding != "linear" && encoding != "sRGB")
    approximations_.push_back(fmt::format("Texture '{}' encoding \"{}\" as sRGB", name, encoding));
  const std::string context = fmt::format("{}:{}: Texture", p.source, p.line);
  try {
    t.image = textures_->load(resolve(p, "filename", file), enc, w, w, context, {},
                              is_float ? TextureContent::data : TextureContent::color_own_gamut);
  } catch (const IoError& e) {
    throw IoError(fmt::format("{}: {}", context, e.what()));
  }
  // pbrt-v4 looks images up at t = 1 − (vscale·v + vdelta) with v up the image (uvs are
  // flipped in pbrt_shapes.cpp; texture_cache.h turns that into Prism's addressing).
  const double su = p.get_float("uscale", 1.0), sv = p.get_float("vscale", 1.0);
  const double du = p.get_float("udelta", 0.0), dv = p.get_float("vdelta", 0.0);
  const bool invert = p.get_bool("invert", false);
  // An inverted texture is a copy of its own (the uv transform's copy, or an identity one).
  if (su != 1.0 || sv != 1.0 || du != 0.0 || dv != 0.0 || invert)
    t.image = textures_->add_with_uv_transform(t.image, su, sv, du, dv);
  const double scale = p.get_float("scale", 1.0);
  t.value = Vec3f(static_cast<float>(scale));
  if (invert) {
    // pbrt-v4 inverts the scaled value, max(0, 1 − scale · v): scale is baked in with it.
    invert_texture_values(scene_.textures[static_cast<std::size_t>(t.image)], static_cast<float>(scale));
    t.value = Vec3f(1.0f);
  }
  for (const char* n : {"filter", "maxanisotropy"}) p.find(n);
  return t;
}

void PbrtBuilder::texture(const std::string& name, const std::string& value_type, const std::string& klass,
                          const PbrtParams& p) {
  PbrtTexture t;
  if (value_type != "spectrum" && value_type != "float")
    throw SceneError(fmt::format("{}:{}: Texture '{}': type must be \"spectrum\" or \"float\"", p.source, p.line, name));
  const bool is_float = value_type == "float";
  if (klass == "constant") {
    if (is_float) t.value = Vec3f(static_cast<float>(p.get_float("value", 1.0)));
    else if (auto c = p.get_color("value", PbrtSpectrumUse::reflectance, state_.color_space, approximations_)) {
      t.value = c->rgb;
      t.space = c->space;
    }
  } else if (klass == "imagemap") {
    t = imagemap(name, p, is_float);
  } else {
    ignore(fmt::format("Texture \"{}\" '{}' (treated as constant 1)", klass, name), p);
    for (const auto& param : p.params) param.used = true;
  }
  note_unused(fmt::format("Texture '{}'", name), p);
  // Float textures are read only as a Shape's "alpha" (pbrt_alpha.cpp).
  (is_float ? float_textures_ : named_textures_)[name] = t;
}

}  // namespace prism::loaders
