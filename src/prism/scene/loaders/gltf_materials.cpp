// glTF 2.0 materials → Prism materials: PBR metallic-roughness with textures, emission
// (KHR_materials_emissive_strength), transmission + ior (→ dielectric), texture
// transforms and alpha modes. Mapping in docs/scene-formats.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/scene/dielectric_ior.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/gltf_builder.h"
#include "prism/scene/loaders/path_safety.h"

namespace prism::loaders {
namespace {

double number(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const auto& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& map, const char* name) {
  const auto it = map.find(name);
  return it == map.end() ? nullptr : &it->second;
}

TextureWrap wrap_mode(int mode) {
  if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::clamp;
  if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::mirror;
  return TextureWrap::repeat;
}

Vec3f factor3(const std::vector<double>& v, Vec3f fallback) {
  if (v.size() < 3) return fallback;
  return Vec3f(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

// An extension's array of three numbers, or nullopt where it is absent or not one.
std::optional<Vec3f> number3(const tinygltf::Value& object, const char* key) {
  if (!object.IsObject() || !object.Has(key)) return std::nullopt;
  const auto& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 3) return std::nullopt;
  Vec3f out;
  for (int i = 0; i < 3; ++i) {
    if (!v.Get(i).IsNumber()) return std::nullopt;
    out[i] = static_cast<float>(v.Get(i).GetNumberAsDouble());
  }
  return out;
}

// The texture index an extension's textureInfo names (-1 where it has none).
int extension_texture_index(const tinygltf::Value& object, const char* key) {
  if (!object.IsObject() || !object.Has(key)) return -1;
  const auto& info = object.Get(key);
  return info.IsObject() && info.Has("index") && info.Get("index").IsInt() ? info.Get("index").GetNumberAsInt() : -1;
}

// glTF's colour textures are its sRGB-encoded ones (base colour, emission, sheen and
// specular colours); the rest are data.
TextureContent content_of(TextureEncoding encoding) {
  return encoding == TextureEncoding::srgb ? TextureContent::color : TextureContent::data;
}

}  // namespace

int GltfBuilder::texture(const tinygltf::TextureInfo& info, TextureEncoding encoding, const std::string& where) {
  if (info.index < 0) return -1;
  if (info.texCoord != 0) warnings_.push_back(fmt::format("glTF: {}: texCoord {} used as TEXCOORD_0", where, info.texCoord));
  return texture(info.index, info.extensions, encoding, where);
}

int GltfBuilder::texture(int index, const tinygltf::ExtensionMap& extensions, TextureEncoding encoding,
                         const std::string& where) {
  if (index < 0 || index >= static_cast<int>(model_.textures.size())) fail(fmt::format("{}: texture {} does not exist", where, index));
  const tinygltf::Texture& t = model_.textures[index];
  if (t.source < 0 || t.source >= static_cast<int>(model_.images.size())) fail(fmt::format("{}: texture {} has no image", where, index));
  TextureWrap wrap_s = TextureWrap::repeat, wrap_t = TextureWrap::repeat;
  if (t.sampler >= 0 && t.sampler < static_cast<int>(model_.samplers.size())) {
    wrap_s = wrap_mode(model_.samplers[t.sampler].wrapS);
    wrap_t = wrap_mode(model_.samplers[t.sampler].wrapT);
  }
  int result = -1;
  const auto key = std::make_pair(t.source, encoding);
  if (const auto it = image_textures_.find(key); it != image_textures_.end()) {
    result = it->second;
  } else {
    const tinygltf::Image& image = model_.images[t.source];
    if (image.image.empty()) fail(fmt::format("{}: image {} has no data", where, t.source));
    TextureImage decoded;
    if (auto ahead = decoded_images_.find(key); ahead != decoded_images_.end()) {
      if (ahead->second.error) std::rethrow_exception(ahead->second.error);
      decoded = std::move(*ahead->second.image);
      decoded_images_.erase(ahead);
    } else {
      decoded = decode_texture_memory(image.image, image_name(t.source), encoding,
                                      {options_.max_texture_dimension, options_.memory_budget}, content_of(encoding),
                                      ImageColorTagUse::ignore);  // glTF 2.0 §3.8.3
    }
    if (!decoded.primaries_note.empty()) warnings_.push_back(decoded.primaries_note);
    scene_.textures.push_back(std::move(decoded));
    result = static_cast<int>(scene_.textures.size() - 1);
    image_textures_[key] = result;
  }
  const TextureImage& base = scene_.textures[result];
  float offset_u = 0.0f, offset_v = 0.0f, scale_u = 1.0f, scale_v = 1.0f, rotation = 0.0f;
  if (const tinygltf::Value* tt = extension(extensions, "KHR_texture_transform")) {
    if (tt->Has("offset") && tt->Get("offset").ArrayLen() == 2) {
      offset_u = static_cast<float>(tt->Get("offset").Get(0).GetNumberAsDouble());
      offset_v = static_cast<float>(tt->Get("offset").Get(1).GetNumberAsDouble());
    }
    if (tt->Has("scale") && tt->Get("scale").ArrayLen() == 2) {
      scale_u = static_cast<float>(tt->Get("scale").Get(0).GetNumberAsDouble());
      scale_v = static_cast<float>(tt->Get("scale").Get(1).GetNumberAsDouble());
    }
    rotation = static_cast<float>(number(*tt, "rotation", 0.0));
    if (tt->Has("texCoord")) warnings_.push_back(fmt::format("glTF: {}: KHR_texture_transform texCoord ignored", where));
  }
  if (base.wrap_u == wrap_s && base.wrap_v == wrap_t && offset_u == 0.0f && offset_v == 0.0f && scale_u == 1.0f &&
      scale_v == 1.0f && rotation == 0.0f)
    return result;
  TextureImage copy = base;  // the same texels with other addressing
  copy.wrap_u = wrap_s;
  copy.wrap_v = wrap_t;
  copy.offset_u = offset_u, copy.offset_v = offset_v, copy.scale_u = scale_u, copy.scale_v = scale_v;
  copy.rotation_radians = rotation;
  if (!std::isfinite(offset_u + offset_v + scale_u + scale_v + rotation))
    fail(fmt::format("{}: KHR_texture_transform values are not finite", where));
  scene_.textures.push_back(std::move(copy));
  return static_cast<int>(scene_.textures.size() - 1);
}

std::string GltfBuilder::image_name(int source) const {
  const tinygltf::Image& image = model_.images[static_cast<std::size_t>(source)];
  if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) return image.uri;
  return fmt::format("{}#image{}", source_, source);
}

// The materials' images, decoded before the materials are built, on all threads: JPEG and
// PNG decoding is most of a textured glTF's load. Each (image, encoding) is decoded once,
// in the order the materials first use it; what a decode throws is kept and thrown when
// texture() comes to that image, so errors are the ones, and in the order, of decoding
// one image after another. The memory budget: decoding one at a time needs each image's
// decoder buffer only next to the texels decoded before it; decoding them together needs
// every buffer at once. So images are decoded ahead only when all their texels and all
// their buffers fit in the budget together (then every reservation succeeds, in any
// order); otherwise texture() decodes them one at a time as before.
void GltfBuilder::decode_images_in_parallel() {
  std::vector<std::pair<int, TextureEncoding>> keys;
  const auto use = [&](int texture_index, TextureEncoding encoding) {
    if (texture_index < 0 || texture_index >= static_cast<int>(model_.textures.size())) return;
    const int source = model_.textures[static_cast<std::size_t>(texture_index)].source;
    if (source < 0 || source >= static_cast<int>(model_.images.size())) return;
    if (model_.images[static_cast<std::size_t>(source)].image.empty()) return;
    const auto key = std::make_pair(source, encoding);
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  };
  for (const tinygltf::Material& m : model_.materials) {  // make_material's order
    use(m.pbrMetallicRoughness.baseColorTexture.index, TextureEncoding::srgb);
    use(m.pbrMetallicRoughness.metallicRoughnessTexture.index, TextureEncoding::linear);
    use(m.emissiveTexture.index, TextureEncoding::srgb);
    use(m.normalTexture.index, TextureEncoding::linear);
    if (const tinygltf::Value* coat = extension(m.extensions, "KHR_materials_clearcoat")) {
      use(extension_texture_index(*coat, "clearcoatTexture"), TextureEncoding::linear);
      use(extension_texture_index(*coat, "clearcoatRoughnessTexture"), TextureEncoding::linear);
    }
  }
  if (keys.size() < 2) return;
  if (MemoryBudget* budget = options_.memory_budget; budget && budget->limit_bytes() > 0) {
    std::uint64_t together = 0;
    for (const auto& [source, encoding] : keys) {
      const auto need = texture_memory_need(model_.images[static_cast<std::size_t>(source)].image);
      if (!need) return;  // a header that does not read: one at a time, as before
      together += need->texel_bytes + need->transient_bytes;
    }
    if (budget->used_bytes() + together > budget->limit_bytes()) return;
  }
  std::vector<DecodedImage> decoded(keys.size());
  parallel_for(keys.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const auto [source, encoding] = keys[k];
      try {
        decoded[k].image = decode_texture_memory(model_.images[static_cast<std::size_t>(source)].image,
                                                 image_name(source), encoding,
                                                 {options_.max_texture_dimension, options_.memory_budget},
                                                 content_of(encoding), ImageColorTagUse::ignore);
      } catch (...) {
        decoded[k].error = std::current_exception();
      }
    }
  });
  for (std::size_t k = 0; k < keys.size(); ++k) decoded_images_[keys[k]] = std::move(decoded[k]);
}

Material GltfBuilder::make_material(const tinygltf::Material& src, int index) {
  const std::string where = fmt::format("materials[{}]", index);
  Material m;
  m.name = src.name.empty() ? where : src.name;
  m.type = MaterialType::metallic_roughness;
  const auto& pbr = src.pbrMetallicRoughness;
  m.base_color = factor3(pbr.baseColorFactor, Vec3f(1.0f));
  m.opacity = pbr.baseColorFactor.size() == 4 ? static_cast<float>(pbr.baseColorFactor[3]) : 1.0f;
  m.metallic = static_cast<float>(pbr.metallicFactor);
  m.roughness = static_cast<float>(pbr.roughnessFactor);
  if (!std::isfinite(m.metallic) || !std::isfinite(m.roughness) || !std::isfinite(m.opacity) ||
      !std::isfinite(m.base_color.x + m.base_color.y + m.base_color.z))
    fail(fmt::format("{}: factors must be finite", where));
  m.metallic = std::clamp(m.metallic, 0.0f, 1.0f);
  m.roughness = std::clamp(m.roughness, 0.0f, 1.0f);
  m.opacity = std::clamp(m.opacity, 0.0f, 1.0f);
  m.base_color_texture = texture(pbr.baseColorTexture, TextureEncoding::srgb, where + ".baseColorTexture");
  m.metallic_roughness_texture =
      texture(pbr.metallicRoughnessTexture, TextureEncoding::linear, where + ".metallicRoughnessTexture");
  if (const tinygltf::Value* specular = extension(src.extensions, "KHR_materials_specular"))
    read_specular(m, *specular, where);
  if (src.alphaMode == "MASK") m.alpha_mode = AlphaMode::mask;
  else if (src.alphaMode == "BLEND") m.alpha_mode = AlphaMode::blend;
  m.alpha_cutoff = static_cast<float>(src.alphaCutoff);

  // Emission: glTF's emissive factor is a linear colour; KHR_materials_emissive_strength
  // multiplies it. We map emissive (1, 1, 1) at strength 1 to a luminance of 1 nit, so the
  // luminance is the factor's CIE Y times the strength (documented in scene-formats.md).
  const Vec3f emissive = factor3(src.emissiveFactor, Vec3f(0.0f));
  double strength = 1.0;
  if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_emissive_strength"))
    strength = number(*e, "emissiveStrength", 1.0);
  if (!(strength >= 0.0) || !std::isfinite(strength)) fail(fmt::format("{}: emissiveStrength must be ≥ 0", where));
  if (max_component(emissive) > 0.0f) {
    m.emission.color = emissive;
    m.emission.luminance_nits = static_cast<float>(relative_luminance(emissive, ColorPickerSpace::srgb) * strength);
    m.emission.texture = texture(src.emissiveTexture, TextureEncoding::srgb, where + ".emissiveTexture");
    m.emission.two_sided = src.doubleSided;
  }

  const tinygltf::Value* transmission = extension(src.extensions, "KHR_materials_transmission");
  const tinygltf::Value* ior = extension(src.extensions, "KHR_materials_ior");
  if (ior) {
    const double eta = number(*ior, "ior", 1.5);
    if (!(eta >= 1.0 && eta <= 10.0) && eta != 0.0) fail(fmt::format("{}: ior must be between 1 and 10", where));
    m.ior = static_cast<float>(eta == 0.0 ? 1.5 : eta);
  }
  if (transmission) {
    m.transmission = static_cast<float>(std::clamp(number(*transmission, "transmissionFactor", 0.0), 0.0, 1.0));
    if (m.transmission > 0.0f) {
      // A transmissive glTF material becomes Prism's dielectric, tinted by the base colour.
      m.type = MaterialType::dielectric;
      m.specular_texture = m.specular_color_texture = -1;  // the specular layer is metallic_roughness'
      read_volume(m, extension(src.extensions, "KHR_materials_volume"), where);
      if (const tinygltf::Value* dispersion = extension(src.extensions, "KHR_materials_dispersion"))
        read_dispersion(m, *dispersion, where);
      if (m.transmission < 1.0f || m.metallic > 0.0f)
        warnings_.push_back(fmt::format("glTF: {}: partial transmission/metallic mixed into a dielectric", where));
    }
  }
  if (m.type != MaterialType::dielectric && extension(src.extensions, "KHR_materials_dispersion"))
    warnings_.push_back(fmt::format(
        "glTF: {}.extensions.KHR_materials_dispersion: ignored on a material that does not transmit", where));
  if (const tinygltf::Value* clearcoat = extension(src.extensions, "KHR_materials_clearcoat"))
    read_clearcoat(m, *clearcoat, where);
  if (const tinygltf::Value* sheen = extension(src.extensions, "KHR_materials_sheen")) read_sheen(m, *sheen, where);
  if (const tinygltf::Value* iridescence = extension(src.extensions, "KHR_materials_iridescence"))
    read_iridescence(m, *iridescence, where);
  if (const tinygltf::Value* anisotropy = extension(src.extensions, "KHR_materials_anisotropy"))
    read_anisotropy(m, *anisotropy, where);
  // Occlusion is meaningless for a path tracer (the transport computes it) and is ignored.
  if (src.normalTexture.index >= 0) {
    const std::string normal_where = where + ".normalTexture";
    if (src.normalTexture.texCoord != 0)
      warnings_.push_back(
          fmt::format("glTF: {}: texCoord {} used as TEXCOORD_0", normal_where, src.normalTexture.texCoord));
    m.normal_texture =
        texture(src.normalTexture.index, src.normalTexture.extensions, TextureEncoding::linear, normal_where);
    m.normal_scale = static_cast<float>(src.normalTexture.scale);
    if (!std::isfinite(m.normal_scale)) fail(fmt::format("{}: scale is not finite", normal_where));
    if (scene_.textures[static_cast<std::size_t>(m.normal_texture)].channels < 3) {
      warnings_.push_back(
          fmt::format("glTF: {}: a normal map needs RGB (the image has fewer channels); ignored", normal_where));
      m.normal_texture = -1;
    }
  }
  return m;
}

// KHR_materials_volume on a transmitting material: without it, or with its default
// thicknessFactor of 0, the surface is thin-walled (the extension: "If the value is 0 the
// material is thin-walled"); otherwise it bounds a volume, which absorbs by
// attenuationColor (default white) after attenuationDistance (default +∞: clear). The
// thickness itself only feeds rasterisers' refraction estimates; a path tracer has the
// real geometry.
void GltfBuilder::read_volume(Material& m, const tinygltf::Value* volume, const std::string& where) {
  const std::string volume_where = where + ".extensions.KHR_materials_volume";
  const double thickness = volume ? number(*volume, "thicknessFactor", 0.0) : 0.0;
  if (!(thickness >= 0.0) || !std::isfinite(thickness))
    fail(fmt::format("{}: thicknessFactor must be ≥ 0", volume_where));
  m.thin_walled = thickness == 0.0;
  if (!volume) return;
  const double distance = number(*volume, "attenuationDistance", std::numeric_limits<double>::infinity());
  if (!(distance > 0.0)) fail(fmt::format("{}: attenuationDistance must be > 0", volume_where));
  Vec3f color(1.0f);
  if (volume->Has("attenuationColor")) {
    const auto c = number3(*volume, "attenuationColor");
    if (!c) fail(fmt::format("{}: attenuationColor must be an array of three numbers", volume_where));
    if (!(min_component(*c) >= 0.0f && max_component(*c) <= 1.0f))
      fail(fmt::format("{}: attenuationColor components must be in [0, 1]", volume_where));
    color = *c;
  }
  const bool absorbs = std::isfinite(distance) && min_component(color) < 1.0f;
  if (absorbs && m.thin_walled) {
    warnings_.push_back(fmt::format(
        "glTF: {}: attenuation ignored: thicknessFactor 0 makes the surface thin-walled, with no inside", volume_where));
    return;
  }
  // A component of exactly 0 (allowed by the extension) absorbs everything at once; the
  // renderer clamps it to 1e-30 (render/volume_absorption.h).
  m.attenuation_color = color;
  m.attenuation_distance = std::isfinite(distance)
                               ? static_cast<float>(std::min(distance, double(std::numeric_limits<float>::max())))
                               : std::numeric_limits<float>::infinity();
}

// KHR_materials_dispersion on a transmitting material: `dispersion` = 20/V_d (default 0:
// none) makes the glass a two-term Cauchy one with n_d = the material's ior and Abbe
// number V_d (bsdf::CauchyIor::from_abbe_number, the extension's own model). Spectral
// transport refracts each wavelength by its own index; RGB transport uses n_d.
void GltfBuilder::read_dispersion(Material& m, const tinygltf::Value& dispersion, const std::string& where) {
  const double strength = number(dispersion, "dispersion", 0.0);
  if (!(strength >= 0.0) || !std::isfinite(strength))
    fail(fmt::format("{}.extensions.KHR_materials_dispersion: dispersion must be finite and ≥ 0", where));
  if (strength == 0.0 || m.ior == 1.0f) return;
  set_cauchy_dispersion(m, bsdf::CauchyIor::from_abbe_number(m.ior, 20.0 / strength));
}

// KHR_materials_specular: the dielectric specular layer's weight (specularFactor, default 1)
// and colour (specularColorFactor, default white; F0 = ((η − 1)/(η + 1))² × colour per
// component, so a colour above 1 may raise it, up to 1). specularTexture's A channel (linear)
// multiplies the weight, specularColorTexture (sRGB-encoded) the colour. Factor 0 on a plain
// dielectric (metallic 0, no metallic-roughness texture) removes the layer, whatever its
// textures: Prism's diffuse, exactly (its own GLB writer says so).
void GltfBuilder::read_specular(Material& m, const tinygltf::Value& specular, const std::string& where) {
  const std::string specular_where = where + ".extensions.KHR_materials_specular";
  const double factor = number(specular, "specularFactor", 1.0);
  if (!(factor >= 0.0 && factor <= 1.0)) fail(fmt::format("{}: specularFactor must be in [0, 1]", specular_where));
  Vec3f color(1.0f);
  if (specular.Has("specularColorFactor")) {
    const auto c = number3(specular, "specularColorFactor");
    if (!c) fail(fmt::format("{}: specularColorFactor must be an array of three numbers", specular_where));
    if (!(min_component(*c) >= 0.0f) || !std::isfinite(max_component(*c)))
      fail(fmt::format("{}: specularColorFactor components must be finite and ≥ 0", specular_where));
    color = *c;
  }
  if (factor == 0.0 && m.metallic == 0.0f && m.metallic_roughness_texture < 0) {
    m.type = MaterialType::diffuse;
    return;
  }
  m.specular = static_cast<float>(factor);
  m.specular_color = color;
  m.specular_texture = extension_texture(specular, "specularTexture", TextureEncoding::linear, specular_where);
  m.specular_color_texture =
      extension_texture(specular, "specularColorTexture", TextureEncoding::srgb, specular_where);
}

// KHR_materials_iridescence: iridescenceFactor ∈ [0, 1] (default 0: no film),
// iridescenceIor ≥ 1 (default 1.3), iridescenceThicknessMinimum / Maximum ≥ 0 in nm
// (defaults 100 and 400), iridescenceTexture (R) and iridescenceThicknessTexture (G),
// linear data. Prism's film goes on metallic_roughness materials, not on glass.
void GltfBuilder::read_iridescence(Material& m, const tinygltf::Value& iridescence, const std::string& where) {
  const std::string film_where = where + ".extensions.KHR_materials_iridescence";
  const double factor = number(iridescence, "iridescenceFactor", 0.0);
  if (!(factor >= 0.0 && factor <= 1.0)) fail(fmt::format("{}: iridescenceFactor must be in [0, 1]", film_where));
  const double ior = number(iridescence, "iridescenceIor", 1.3);
  if (!(ior >= 1.0 && ior <= 10.0)) fail(fmt::format("{}: iridescenceIor must be between 1 and 10", film_where));
  const double thinnest = number(iridescence, "iridescenceThicknessMinimum", 100.0);
  const double thickest = number(iridescence, "iridescenceThicknessMaximum", 400.0);
  for (const double d : {thinnest, thickest})
    if (!(d >= 0.0 && d <= 1e5))
      fail(fmt::format("{}: iridescenceThicknessMinimum and Maximum must be in [0, 100000] nm", film_where));
  if (factor == 0.0) return;  // no film
  // specularFactor 0 made Lambert of a plain dielectric (read_specular); under a film it
  // stays the metallic_roughness material it is, its specular layer weighted 0.
  if (m.type == MaterialType::diffuse) m.type = MaterialType::metallic_roughness, m.specular = 0.0f;
  if (m.type != MaterialType::metallic_roughness) {
    warnings_.push_back(
        fmt::format("glTF: {}: ignored on a transmitting material (Prism puts no thin film on glass)", film_where));
    return;
  }
  m.iridescence = static_cast<float>(factor);
  m.iridescence_ior = static_cast<float>(ior);
  m.iridescence_thickness_min_nm = static_cast<float>(thinnest);
  m.iridescence_thickness_max_nm = static_cast<float>(thickest);
  m.iridescence_texture = extension_texture(iridescence, "iridescenceTexture", TextureEncoding::linear, film_where);
  m.iridescence_thickness_texture =
      extension_texture(iridescence, "iridescenceThicknessTexture", TextureEncoding::linear, film_where);
}

// KHR_materials_anisotropy: anisotropyStrength ∈ [0, 1] (default 0), anisotropyRotation in
// radians counter-clockwise from the tangent (default 0) and anisotropyTexture (linear: RG
// the direction in tangent space, B the strength), render/anisotropy.h. It stretches the
// microfacet lobe of whatever the material became (metallic_roughness or glass; a Lambert
// of specularFactor 0 has no lobe to stretch).
void GltfBuilder::read_anisotropy(Material& m, const tinygltf::Value& anisotropy, const std::string& where) {
  const std::string anisotropy_where = where + ".extensions.KHR_materials_anisotropy";
  const double strength = number(anisotropy, "anisotropyStrength", 0.0);
  if (!(strength >= 0.0 && strength <= 1.0))
    fail(fmt::format("{}: anisotropyStrength must be in [0, 1]", anisotropy_where));
  const double rotation = number(anisotropy, "anisotropyRotation", 0.0);
  if (!std::isfinite(rotation)) fail(fmt::format("{}: anisotropyRotation is not finite", anisotropy_where));
  m.anisotropy = static_cast<float>(strength);
  m.anisotropy_rotation_rad = static_cast<float>(std::remainder(rotation, 2.0 * std::numbers::pi));
  m.anisotropy_texture = extension_texture(anisotropy, "anisotropyTexture", TextureEncoding::linear, anisotropy_where);
}

// An extension's textureInfo (an object with "index", optional "texCoord" and its own
// extensions, KHR_texture_transform among them), as Prism texture; -1 where it is absent.
int GltfBuilder::extension_texture(const tinygltf::Value& object, const char* key, TextureEncoding encoding,
                                   const std::string& where) {
  if (!object.Has(key)) return -1;
  const std::string texture_where = where + "." + key;
  const tinygltf::Value& info = object.Get(key);
  if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
    fail(fmt::format("{}: expected a textureInfo object with an integer index", texture_where));
  const int tex_coord = static_cast<int>(number(info, "texCoord", 0.0));
  if (tex_coord != 0) warnings_.push_back(fmt::format("glTF: {}: texCoord {} used as TEXCOORD_0", texture_where, tex_coord));
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions") && info.Get("extensions").IsObject())
    for (const std::string& name : info.Get("extensions").Keys()) extensions[name] = info.Get("extensions").Get(name);
  return texture(info.Get("index").GetNumberAsInt(), extensions, encoding, texture_where);
}

// KHR_materials_clearcoat: a coat of weight clearcoatFactor × clearcoatTexture.r and
// roughness clearcoatRoughnessFactor × clearcoatRoughnessTexture.g (both default 0, the
// textures linear), η = 1.5, over the metallic-roughness base (bsdf/clearcoat.h).
// clearcoatNormalTexture (a normalTextureInfo: its `scale` multiplies x and y) bends the
// coat alone, around the unmapped vertex normal.
void GltfBuilder::read_clearcoat(Material& m, const tinygltf::Value& clearcoat, const std::string& where) {
  const std::string coat_where = where + ".extensions.KHR_materials_clearcoat";
  const double weight = number(clearcoat, "clearcoatFactor", 0.0);
  const double roughness = number(clearcoat, "clearcoatRoughnessFactor", 0.0);
  if (!(weight >= 0.0 && weight <= 1.0)) fail(fmt::format("{}: clearcoatFactor must be in [0, 1]", coat_where));
  if (!(roughness >= 0.0 && roughness <= 1.0))
    fail(fmt::format("{}: clearcoatRoughnessFactor must be in [0, 1]", coat_where));
  if (weight == 0.0) return;  // the extension's default: no coat, whatever the textures say
  if (m.type == MaterialType::dielectric) {
    warnings_.push_back(fmt::format("glTF: {}: ignored on a transmitting material (Prism coats no glass)", coat_where));
    return;
  }
  m.clearcoat = static_cast<float>(weight);
  m.clearcoat_roughness = static_cast<float>(roughness);
  m.clearcoat_texture = extension_texture(clearcoat, "clearcoatTexture", TextureEncoding::linear, coat_where);
  m.clearcoat_roughness_texture =
      extension_texture(clearcoat, "clearcoatRoughnessTexture", TextureEncoding::linear, coat_where);
  m.clearcoat_normal_texture =
      extension_texture(clearcoat, "clearcoatNormalTexture", TextureEncoding::linear, coat_where);
  if (m.clearcoat_normal_texture >= 0) {
    const tinygltf::Value& info = clearcoat.Get("clearcoatNormalTexture");
    const double scale = number(info, "scale", 1.0);
    if (!std::isfinite(scale)) fail(fmt::format("{}.clearcoatNormalTexture: scale is not finite", coat_where));
    m.clearcoat_normal_scale = static_cast<float>(scale);
    if (scene_.textures[static_cast<std::size_t>(m.clearcoat_normal_texture)].channels < 3) {
      warnings_.push_back(fmt::format(
          "glTF: {}.clearcoatNormalTexture: a normal map needs RGB (the image has fewer channels); ignored", coat_where));
      m.clearcoat_normal_texture = -1;
    }
  }
}

// KHR_materials_sheen: sheenColorFactor (default black: no sheen) and sheenRoughnessFactor
// (default 0), each in [0, 1]; sheenColorTexture is a colour (sRGB-encoded), the A channel
// of sheenRoughnessTexture linear data. Prism puts no sheen on glass.
void GltfBuilder::read_sheen(Material& m, const tinygltf::Value& sheen, const std::string& where) {
  const std::string sheen_where = where + ".extensions.KHR_materials_sheen";
  Vec3f color(0.0f);
  if (sheen.Has("sheenColorFactor")) {
    const auto c = number3(sheen, "sheenColorFactor");
    if (!c) fail(fmt::format("{}: sheenColorFactor must be an array of three numbers", sheen_where));
    if (!(min_component(*c) >= 0.0f && max_component(*c) <= 1.0f))
      fail(fmt::format("{}: sheenColorFactor components must be in [0, 1]", sheen_where));
    color = *c;
  }
  const double roughness = number(sheen, "sheenRoughnessFactor", 0.0);
  if (!(roughness >= 0.0 && roughness <= 1.0))
    fail(fmt::format("{}: sheenRoughnessFactor must be in [0, 1]", sheen_where));
  if (max_component(color) == 0.0f) return;  // the extension: a black sheen disables the layer
  if (m.type == MaterialType::dielectric) {
    warnings_.push_back(fmt::format("glTF: {}: ignored on a transmitting material (Prism puts no sheen on glass)",
                                    sheen_where));
    return;
  }
  m.sheen_color = color;
  m.sheen_roughness = static_cast<float>(roughness);
  m.sheen_color_texture = extension_texture(sheen, "sheenColorTexture", TextureEncoding::srgb, sheen_where);
  m.sheen_roughness_texture = extension_texture(sheen, "sheenRoughnessTexture", TextureEncoding::linear, sheen_where);
}

void GltfBuilder::build_materials() {
  for (std::size_t i = 0; i < model_.materials.size(); ++i)
    scene_.materials.push_back(make_material(model_.materials[i], static_cast<int>(i)));
}

}  // namespace prism::loaders
