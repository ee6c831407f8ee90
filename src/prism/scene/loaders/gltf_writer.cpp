#include "prism/scene/loaders/gltf_writer.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "prism/bsdf/conductor_color.h"
#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/scene/dielectric_ior.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/texture_png.h"

namespace prism::loaders {
namespace {

using nlohmann::json;

class BinaryChunk {
 public:
  // Appends raw data as a buffer view + accessor; returns the accessor index.
  int add(json& doc, const void* data, std::size_t bytes, std::size_t count, const char* type, int component_type,
          int target, const json& extra = json::object()) {
    while (bin_.size() % 4) bin_.push_back('\0');
    const std::size_t offset = bin_.size();
    bin_.append(static_cast<const char*>(data), bytes);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
    json accessor = {{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", component_type},
                     {"count", count}, {"type", type}};
    accessor.update(extra);
    doc["accessors"].push_back(accessor);
    return static_cast<int>(doc["accessors"].size() - 1);
  }
  // Appends raw bytes as a buffer view without a target (an embedded image); returns the view.
  int add_view(json& doc, const std::vector<unsigned char>& data) {
    while (bin_.size() % 4) bin_.push_back('\0');
    const std::size_t offset = bin_.size();
    bin_.append(reinterpret_cast<const char*>(data.data()), data.size());
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", data.size()}});
    return static_cast<int>(doc["bufferViews"].size() - 1);
  }
  std::string& bytes() { return bin_; }

 private:
  std::string bin_;
};

int wrap_code(TextureWrap w) {
  switch (w) {
    case TextureWrap::repeat: return 10497;
    case TextureWrap::clamp: return 33071;
    case TextureWrap::mirror: return 33648;
  }
  return 10497;
}

bool has_uv_transform(const TextureImage& t) {
  return t.offset_u != 0.0f || t.offset_v != 0.0f || t.scale_u != 1.0f || t.scale_v != 1.0f || t.rotation_radians != 0.0f;
}

// A textureInfo: the texture (one per image, same index) and its uv transform, if any.
json texture_info(const Scene& scene, int index) {
  json info = {{"index", index}};
  const TextureImage& t = scene.textures[static_cast<std::size_t>(index)];
  if (has_uv_transform(t))
    info["extensions"]["KHR_texture_transform"] = {
        {"offset", {t.offset_u, t.offset_v}}, {"scale", {t.scale_u, t.scale_v}}, {"rotation", t.rotation_radians}};
  return info;
}

// glTF 2.0's colours are linear Rec.709: one given in another space is converted, and
// refused where it lies outside Rec.709 (clipped, it would be another colour).
Vec3f rec709_color(const Vec3f& color, ColorPickerSpace space, const Material& m, std::string_view what) {
  if (auto c = picker_color_within_rec709(color, space)) return *c;
  throw UsageError(fmt::format("GLB writer: material '{}': its {} ({}) lies outside Rec.709, which glTF 2.0's colours "
                               "are limited to",
                               m.name, what, picker_space_name(space)));
}

json material_json(const Scene& scene, const Material& m) {
  json j = {{"name", m.name}};
  // A texture multiplies a wide-gamut factor in the material's space and glTF's in Rec.709:
  // the same colour only for a grey factor (Material::base_color_space).
  const Vec3f& f = m.base_color;
  if (m.base_color_texture >= 0 && m.base_color_space != ColorPickerSpace::srgb && (f.x != f.y || f.x != f.z))
    throw UsageError(fmt::format("GLB writer: material '{}': a texture tinted in {}, which glTF 2.0 cannot say", m.name,
                                 picker_space_name(m.base_color_space)));
  const Vec3f base = rec709_color(m.base_color, m.base_color_space, m, "base colour");
  json pbr = {{"baseColorFactor", {base.x, base.y, base.z, m.opacity}},
              {"metallicFactor", 0.0}, {"roughnessFactor", m.roughness}};
  switch (m.type) {
    case MaterialType::diffuse:
      // Lambert: metallic 0 and no specular layer (KHR_materials_specular factor 0).
      pbr["roughnessFactor"] = 1.0;
      j["extensions"]["KHR_materials_specular"] = {{"specularFactor", 0.0}};
      break;
    case MaterialType::mirror: pbr["metallicFactor"] = 1.0, pbr["roughnessFactor"] = 0.0; break;
    case MaterialType::conductor: {
      pbr["metallicFactor"] = 1.0;
      if (m.conductor_fresnel == ConductorFresnel::complex_ior) {
        // The colour of the metal's spectral F0 from the same η, k data the conductor
        // renders with (docs/scene-formats.md lists what glTF still cannot express).
        const Vec3f f0 = bsdf::conductor_f0_rec709(m.conductor_name);
        pbr["baseColorFactor"] = {f0.x, f0.y, f0.z, 1.0};
      }
      break;
    }
    case MaterialType::dielectric:
      j["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1.0}};
      j["extensions"]["KHR_materials_ior"] = {{"ior", m.ior}};
      // Dispersion as glTF's 20/V_d: a Cauchy glass comes back exactly, a Sellmeier one as
      // the Cauchy glass of its n_d and Abbe number (docs/scene-formats.md).
      if (m.dispersion != DispersionModel::none) {
        const double dispersion = 20.0 / dielectric_abbe_number(m);
        if (!(dispersion >= 0.0))
          throw UsageError(fmt::format(
              "GLB writer: material '{}' refracts red more than blue, which KHR_materials_dispersion cannot hold", m.name));
        j["extensions"]["KHR_materials_dispersion"] = {{"dispersion", dispersion}};
      }
      // A solid (not thin-walled) dielectric needs KHR_materials_volume: without it glTF
      // readers, Prism's included, take a thin surface. The thickness only feeds
      // rasterisers' refraction approximations.
      if (!m.thin_walled) {
        j["extensions"]["KHR_materials_volume"] = {{"thicknessFactor", 1.0}};
        if (m.absorbs_inside()) {
          const Vec3f& c = m.attenuation_color;
          j["extensions"]["KHR_materials_volume"]["attenuationColor"] = {c.x, c.y, c.z};
          j["extensions"]["KHR_materials_volume"]["attenuationDistance"] = m.attenuation_distance;
        }
      }
      break;
    case MaterialType::metallic_roughness:
      pbr["metallicFactor"] = m.metallic;
      if (m.ior != 1.5f) j["extensions"]["KHR_materials_ior"] = {{"ior", m.ior}};
      if (m.specular != 1.0f || m.specular_color != Vec3f(1.0f) || m.specular_texture >= 0 ||
          m.specular_color_texture >= 0) {
        const Vec3f& c = m.specular_color;
        auto& specular = j["extensions"]["KHR_materials_specular"];
        specular = {{"specularFactor", m.specular}, {"specularColorFactor", {c.x, c.y, c.z}}};
        if (m.specular_texture >= 0) specular["specularTexture"] = texture_info(scene, m.specular_texture);
        if (m.specular_color_texture >= 0)
          specular["specularColorTexture"] = texture_info(scene, m.specular_color_texture);
      }
      break;
  }
  if (m.base_color_texture >= 0) pbr["baseColorTexture"] = texture_info(scene, m.base_color_texture);
  if (m.metallic_roughness_texture >= 0) pbr["metallicRoughnessTexture"] = texture_info(scene, m.metallic_roughness_texture);
  j["pbrMetallicRoughness"] = pbr;
  if (m.has_clearcoat()) {
    auto& coat = j["extensions"]["KHR_materials_clearcoat"];
    coat = {{"clearcoatFactor", m.clearcoat}, {"clearcoatRoughnessFactor", m.clearcoat_roughness}};
    if (m.clearcoat_texture >= 0) coat["clearcoatTexture"] = texture_info(scene, m.clearcoat_texture);
    if (m.clearcoat_roughness_texture >= 0)
      coat["clearcoatRoughnessTexture"] = texture_info(scene, m.clearcoat_roughness_texture);
    if (m.clearcoat_normal_texture >= 0) {
      coat["clearcoatNormalTexture"] = texture_info(scene, m.clearcoat_normal_texture);
      coat["clearcoatNormalTexture"]["scale"] = m.clearcoat_normal_scale;
    }
  }
  if (m.has_iridescence()) {
    auto& film = j["extensions"]["KHR_materials_iridescence"];
    film = {{"iridescenceFactor", m.iridescence},
            {"iridescenceIor", m.iridescence_ior},
            {"iridescenceThicknessMinimum", m.iridescence_thickness_min_nm},
            {"iridescenceThicknessMaximum", m.iridescence_thickness_max_nm}};
    if (m.iridescence_texture >= 0) film["iridescenceTexture"] = texture_info(scene, m.iridescence_texture);
    if (m.iridescence_thickness_texture >= 0)
      film["iridescenceThicknessTexture"] = texture_info(scene, m.iridescence_thickness_texture);
  }
  if (m.anisotropy > 0.0f) {
    auto& anisotropy = j["extensions"]["KHR_materials_anisotropy"];
    anisotropy = {{"anisotropyStrength", m.anisotropy}, {"anisotropyRotation", m.anisotropy_rotation_rad}};
    if (m.anisotropy_texture >= 0) anisotropy["anisotropyTexture"] = texture_info(scene, m.anisotropy_texture);
  }
  if (m.has_sheen()) {
    auto& sheen = j["extensions"]["KHR_materials_sheen"];
    const Vec3f& c = m.sheen_color;
    sheen = {{"sheenColorFactor", {c.x, c.y, c.z}}, {"sheenRoughnessFactor", m.sheen_roughness}};
    if (m.sheen_color_texture >= 0) sheen["sheenColorTexture"] = texture_info(scene, m.sheen_color_texture);
    if (m.sheen_roughness_texture >= 0) sheen["sheenRoughnessTexture"] = texture_info(scene, m.sheen_roughness_texture);
  }
  if (m.bump_texture >= 0)
    throw UsageError(fmt::format("GLB writer: material '{}' has a bump map, which glTF 2.0 cannot hold", m.name));
  if (m.normal_texture >= 0) {
    j["normalTexture"] = texture_info(scene, m.normal_texture);
    j["normalTexture"]["scale"] = m.normal_scale;
  }
  if (m.alpha_mode == AlphaMode::mask) j["alphaMode"] = "MASK", j["alphaCutoff"] = m.alpha_cutoff;
  if (m.alpha_mode == AlphaMode::blend) j["alphaMode"] = "BLEND";
  if (m.alpha_mode != AlphaMode::opaque) j["doubleSided"] = true;  // cards are seen from both sides
  if (m.is_emissive()) {
    // Prism reads emissive (1, 1, 1) × strength 1 as 1 nit: scale the colour to Y = 1.
    if (m.emission.texture >= 0 && m.emission.color_space != ColorPickerSpace::srgb)
      throw UsageError(fmt::format("GLB writer: material '{}': an emission texture tinted in {}, which glTF 2.0 cannot say",
                                   m.name, picker_space_name(m.emission.color_space)));
    const Vec3f emissive = rec709_color(m.emission.color, m.emission.color_space, m, "emission colour");
    const double y = relative_luminance(emissive, ColorPickerSpace::srgb);
    const Vec3f c = emissive / static_cast<float>(std::max(y, 1e-12));
    const float peak = std::max(max_component(c), 1.0f);  // emissiveFactor is limited to [0, 1]
    j["emissiveFactor"] = {c.x / peak, c.y / peak, c.z / peak};
    j["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", m.emission.luminance_nits * peak}};
    if (m.emission.two_sided) j["doubleSided"] = true;
    if (m.emission.texture >= 0) j["emissiveTexture"] = texture_info(scene, m.emission.texture);
  }
  return j;
}

}  // namespace

void write_scene_glb(const Scene& scene, const std::filesystem::path& path) {
  if (!scene.instances.empty()) throw UsageError("glTF writer: instances are not supported");
  for (const Light& l : scene.lights)
    if (l.type != LightType::environment) throw UsageError("glTF writer: punctual lights are not supported");
  for (const Material& m : scene.materials)
    if (m.base_color_spectrum || m.emission.spectrum)
      throw UsageError(fmt::format("glTF writer: material '{}' has a spectrum, which glTF 2.0 cannot hold", m.name));
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "Prism"}}},
              {"bufferViews", json::array()}, {"accessors", json::array()}, {"meshes", json::array()},
              {"materials", json::array()}, {"nodes", json::array()}};
  // extensionsUsed names exactly the extensions the file uses (glTF 2.0 §3.12), in a
  // stable order, and is left out when there are none (the schema wants at least one item).
  std::set<std::string> used;
  for (const Material& m : scene.materials) {
    json j = material_json(scene, m);
    if (j.contains("extensions"))
      for (const auto& [name, value] : j["extensions"].items()) used.insert(name);
    doc["materials"].push_back(std::move(j));
  }
  BinaryChunk bin;
  // Textures: each image embedded as PNG (a buffer view), with its own sampler and texture.
  const std::vector<TextureEncoding> encodings = texture_encodings(scene);
  bool transformed = false;
  for (std::size_t i = 0; i < scene.textures.size(); ++i) {
    const TextureImage& t = scene.textures[i];
    const int view = bin.add_view(doc, encode_texture_png(t, encodings[i]));
    doc["images"].push_back({{"name", t.name}, {"bufferView", view}, {"mimeType", "image/png"}});
    doc["samplers"].push_back({{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", wrap_code(t.wrap_u)}, {"wrapT", wrap_code(t.wrap_v)}});
    doc["textures"].push_back({{"name", t.name}, {"sampler", i}, {"source", i}});
    transformed |= has_uv_transform(t);
  }
  if (transformed) used.insert("KHR_texture_transform");
  if (!used.empty()) doc["extensionsUsed"] = used;
  json scene_nodes = json::array();
  for (const TriangleMesh& mesh : scene.meshes) {
    Vec3f lo(INFINITY), hi(-INFINITY);
    for (const Vec3f& p : mesh.positions) lo = min(lo, p), hi = max(hi, p);
    json attributes;
    attributes["POSITION"] = bin.add(doc, mesh.positions.data(), mesh.positions.size() * sizeof(Vec3f), mesh.positions.size(),
                                     "VEC3", 5126, 34962, {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}});
    if (!mesh.normals.empty())
      attributes["NORMAL"] = bin.add(doc, mesh.normals.data(), mesh.normals.size() * sizeof(Vec3f), mesh.normals.size(), "VEC3", 5126, 34962);
    if (!mesh.uvs.empty())
      attributes["TEXCOORD_0"] = bin.add(doc, mesh.uvs.data(), mesh.uvs.size() * sizeof(Vec2f), mesh.uvs.size(), "VEC2", 5126, 34962);
    const int indices = bin.add(doc, mesh.indices.data(), mesh.indices.size() * 4, mesh.indices.size(), "SCALAR", 5125, 34963);
    doc["meshes"].push_back({{"name", mesh.name},
                             {"primitives", {{{"attributes", attributes}, {"indices", indices}, {"material", mesh.material}}}}});
    doc["nodes"].push_back({{"name", mesh.name}, {"mesh", doc["meshes"].size() - 1}});
    scene_nodes.push_back(doc["nodes"].size() - 1);
  }
  // The camera: glTF cameras look down −z with +y up and +x to the right.
  const Camera& c = scene.camera;
  const Vec3f forward = normalize(c.target - c.eye), right = normalize(cross(forward, c.up)), up = cross(right, forward);
  const double aspect = static_cast<double>(scene.default_width) / scene.default_height;
  const double fov = c.fov_degrees * std::acos(-1.0) / 180.0;
  const double yfov = aspect >= 1.0 ? fov : 2.0 * std::atan(std::tan(fov / 2.0) / aspect);
  doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", yfov}, {"aspectRatio", aspect}, {"znear", 0.01}}}}};
  doc["nodes"].push_back({{"name", c.name.empty() ? "camera" : c.name}, {"camera", 0},
                          {"matrix", {right.x, right.y, right.z, 0, up.x, up.y, up.z, 0, -forward.x, -forward.y, -forward.z, 0,
                                      c.eye.x, c.eye.y, c.eye.z, 1}}});
  scene_nodes.push_back(doc["nodes"].size() - 1);
  doc["scenes"] = {{{"name", scene.name}, {"nodes", scene_nodes}}};
  doc["scene"] = 0;
  std::string& data = bin.bytes();
  while (data.size() % 4) data.push_back('\0');
  doc["buffers"] = {{{"byteLength", data.size()}}};
  std::string text = doc.dump();
  while (text.size() % 4) text.push_back(' ');
  const std::size_t total = 12 + 8 + text.size() + 8 + data.size();
  if (total > 0xffffffffu) throw UsageError("glTF writer: the scene is larger than a GLB file can hold (4 GiB)");
  AtomicFile file(path);
  {
    std::ofstream out(file.temporary_path(), std::ios::binary);
    const auto u32 = [&](std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };  // little-endian hosts
    out.write("glTF", 4);
    u32(2), u32(static_cast<std::uint32_t>(total));
    u32(static_cast<std::uint32_t>(text.size())), u32(0x4E4F534Au);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    u32(static_cast<std::uint32_t>(data.size())), u32(0x004E4942u);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) throw IoError(fmt::format("cannot write '{}'", path.string()));
  }
  file.commit();
}

}  // namespace prism::loaders
