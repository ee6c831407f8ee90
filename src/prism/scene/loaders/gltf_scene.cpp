// glTF 2.0: reading (tinygltf with guarded file access), extensions, the node hierarchy,
// meshes and instancing, cameras and KHR_lights_punctual.
#include "prism/scene/loaders/gltf_scene.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"
#include "prism/io/read_to_end.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/gltf_accessors.h"
#include "prism/scene/loaders/gltf_builder.h"
#include "prism/scene/loaders/mesh_checks.h"
#include "prism/scene/loaders/mesh_tangents.h"
#include "prism/scene/loaders/path_safety.h"
#include "prism/scene/loaders/scene_camera.h"

namespace prism::loaders {
namespace {

constexpr int kMaxNodeDepth = 256;

struct FileGuard {
  std::filesystem::path dir;
  std::string base;     // the folder as tinygltf was given it
  std::string where;    // "scene.gltf: buffer or image uri", for messages
  bool allow_external = false;
  std::string refusal;  // why the first refused uri was refused
};

// tinygltf looks for a uri at JoinPath(base, uri), then at "./" + uri (the process's
// working folder); it passes each through this before asking whether the file exists. The
// first is resolved against the scene's folder by the rule every loader follows
// (path_safety.h); the second is not a reference relative to the scene, and is not looked
// at. A refused uri becomes the empty path (which does not exist), and the reason is kept:
// tinygltf itself would only report "File not found".
std::string expand_path(const std::string& joined, void* user) {
  auto* guard = static_cast<FileGuard*>(user);
  const std::string prefix = guard->base.ends_with('/') ? guard->base : guard->base + "/";
  if (!joined.starts_with(prefix)) return {};
  try {
    return resolve_scene_reference(guard->dir, std::string_view(joined).substr(prefix.size()),
                                   guard->allow_external, guard->where)
        .string();
  } catch (const std::exception& e) {  // not thrown through tinygltf: kept, thrown after it returns
    if (guard->refusal.empty()) guard->refusal = e.what();
    return {};
  }
}

// tinygltf reads buffers and images through these: a file outside the scene's folder is
// refused here, whatever the uri looked like before tinygltf decoded and joined it.
bool guarded_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* guard = static_cast<const FileGuard*>(user);
  std::error_code ec;
  const auto resolved = std::filesystem::weakly_canonical(std::filesystem::path(path), ec);
  if (guard->dir.empty() || ec || (!guard->allow_external && !is_inside_folder(resolved, guard->dir))) {
    if (err) *err += fmt::format("uri '{}' lies outside the scene's folder (use --allow-external-paths)", path);
    return false;
  }
  std::ifstream in(resolved, std::ios::binary);
  if (!in) {
    if (err) *err += fmt::format("cannot read '{}'", path);
    return false;
  }
  if (!read_to_end(in, regular_file_size_or_zero(resolved), *out)) {
    if (err) *err += fmt::format("cannot read '{}'", path);
    return false;
  }
  return true;
}

bool file_exists(const std::string& path, void*) {
  std::error_code ec;
  return !path.empty() && std::filesystem::is_regular_file(path, ec);
}

bool no_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed";
  return false;
}

// Keeps the encoded bytes; Prism's texture reader decodes them later (with its limits).
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + std::max(size, 0));
  image->as_is = true;
  image->width = image->height = -1;
  return true;
}

Transform node_transform(const tinygltf::Node& n) {
  Transform t;
  if (n.matrix.size() == 16) {  // column-major
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) t.m[i][j] = static_cast<float>(n.matrix[j * 4 + i]);
    t.translation = Vec3f(static_cast<float>(n.matrix[12]), static_cast<float>(n.matrix[13]), static_cast<float>(n.matrix[14]));
    return t;
  }
  if (n.scale.size() == 3)
    t = Transform::scale(Vec3f(static_cast<float>(n.scale[0]), static_cast<float>(n.scale[1]), static_cast<float>(n.scale[2])));
  if (n.rotation.size() == 4) {  // unit quaternion (x, y, z, w)
    double x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
    const double len = std::sqrt(x * x + y * y + z * z + w * w);
    if (len > 0.0) x /= len, y /= len, z /= len, w /= len;
    Transform r;
    const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = static_cast<float>(m[i][j]);
    t = compose(r, t);
  }
  if (n.translation.size() == 3)
    t = compose(Transform::translate(Vec3f(static_cast<float>(n.translation[0]), static_cast<float>(n.translation[1]),
                                           static_cast<float>(n.translation[2]))),
                t);
  return t;
}

// A glTF version "MAJOR.MINOR" (the schema's pattern ^[0-9]+\.[0-9]+$), or nothing.
std::optional<std::pair<unsigned long, unsigned long>> parse_gltf_version(std::string_view text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const auto number = [](std::string_view digits) -> std::optional<unsigned long> {
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
    unsigned long value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() ? value : std::numeric_limits<unsigned long>::max();  // too large: no version read
  };
  const auto major = number(text.substr(0, dot)), minor = number(text.substr(dot + 1));
  if (!major || !minor) return std::nullopt;
  return std::pair{*major, *minor};
}

// glTF 2.0 §3.2 (Asset): a reader checks minVersion if it is given (major and minor must
// be supported: the author declares that a reader of that version can read the file),
// otherwise the major version of `version`. Prism reads glTF 2.0; a file of another major
// version is laid out differently and is refused, not guessed at.
void check_gltf_version(const tinygltf::Asset& asset, std::string_view source) {
  const auto version = parse_gltf_version(asset.version);
  if (!version)
    throw SceneError(fmt::format("{}: asset.version '{}' is not a glTF version (MAJOR.MINOR); Prism reads glTF 2.0",
                                 source, asset.version));
  if (!asset.minVersion.empty()) {
    const auto needed = parse_gltf_version(asset.minVersion);
    if (!needed || needed->first != 2 || needed->second > 0)
      throw SceneError(fmt::format("{}: the file needs glTF {} (asset.minVersion); Prism reads glTF 2.0", source,
                                   asset.minVersion));
    return;
  }
  if (version->first != 2)
    throw SceneError(fmt::format("{}: glTF version {} (asset.version) is not supported; Prism reads glTF 2.0",
                                 source, asset.version));
}

bool finite(const Transform& t) {
  for (const auto& row : t.m)
    for (float v : row)
      if (!std::isfinite(v)) return false;
  return std::isfinite(t.translation.x) && std::isfinite(t.translation.y) && std::isfinite(t.translation.z);
}

}  // namespace

GltfBuilder::GltfBuilder(const tinygltf::Model& model, std::string source, const std::filesystem::path& dir,
                         const LoadOptions& options)
    : model_(model), source_(std::move(source)), dir_(dir), options_(options) {}

void GltfBuilder::fail(const std::string& message) const { throw SceneError(fmt::format("{}: {}", source_, message)); }

void GltfBuilder::check_extensions() {
  static const std::vector<std::string> kSupported = {
      "KHR_materials_emissive_strength", "KHR_lights_punctual", "KHR_materials_transmission",
      "KHR_materials_ior",               "KHR_materials_volume", "KHR_texture_transform",
      "KHR_materials_dispersion",  // on transmitting materials: a Cauchy glass of the Abbe number
      "KHR_materials_specular",     // factors and textures (metallic_roughness.h)
      "KHR_materials_clearcoat",    // clearcoatNormalTexture is warned (gltf_materials.cpp)
      "KHR_materials_sheen",        // bsdf/sheen.h; none on glass (warned)
      "KHR_materials_iridescence",  // bsdf/thin_film.h; none on glass (warned)
      "KHR_materials_anisotropy",   // render/anisotropy.h
      "KHR_mesh_quantization",    // integer attributes: gltf_accessors.cpp reads every allowed type
      "KHR_materials_variants"};  // LoadOptions::material_variant picks one
  const auto supported = [](const std::string& e) { return std::find(kSupported.begin(), kSupported.end(), e) != kSupported.end(); };
  std::vector<std::string> unsupported_required, unsupported_used;
  for (const auto& e : model_.extensionsRequired)
    if (!supported(e)) unsupported_required.push_back(e);
  if (!unsupported_required.empty())
    fail(fmt::format("required extension(s) not supported: {}", fmt::join(unsupported_required, ", ")));
  for (const auto& e : model_.extensionsUsed)
    if (!supported(e)) unsupported_used.push_back(e);
  if (!unsupported_used.empty())
    warnings_.push_back(fmt::format("glTF: extensions ignored: {}", fmt::join(unsupported_used, ", ")));
}

const std::vector<std::uint32_t>& GltfBuilder::mesh_primitives(int mesh_index) {
  if (const auto it = meshes_.find(mesh_index); it != meshes_.end()) return it->second;
  std::vector<std::uint32_t> created;
  const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& prim = mesh.primitives[p];
    const std::string where = fmt::format("{}: meshes[{}].primitives[{}]", source_, mesh_index, p);
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
      warnings_.push_back(fmt::format("glTF: {}: mode {} is not triangles, skipped", where, prim.mode));
      continue;
    }
    const auto attribute = [&](const char* name) {
      const auto it = prim.attributes.find(name);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    if (attribute("POSITION") < 0) throw SceneError(fmt::format("{}: no POSITION attribute", where));
    TriangleMesh m;
    m.name = mesh.name.empty() ? fmt::format("mesh{}.{}", mesh_index, p) : fmt::format("{}.{}", mesh.name, p);
    m.positions = read_gltf_vec3(model_, attribute("POSITION"), where);
    if (attribute("NORMAL") >= 0) m.normals = read_gltf_vec3(model_, attribute("NORMAL"), where);
    if (attribute("TEXCOORD_0") >= 0) m.uvs = read_gltf_vec2(model_, attribute("TEXCOORD_0"), where);
    if (attribute("TANGENT") >= 0) {
      m.tangents = read_gltf_vec4_xyz(model_, attribute("TANGENT"), where);
      m.tangent_signs = read_gltf_tangent_signs(model_, attribute("TANGENT"), where);
    }
    if (prim.indices >= 0) {
      m.indices = read_gltf_indices(model_, prim.indices, where);
    } else {
      m.indices.resize(m.positions.size());
      for (std::size_t i = 0; i < m.indices.size(); ++i) m.indices[i] = static_cast<std::uint32_t>(i);
    }
    m.indices.resize(m.indices.size() - m.indices.size() % 3);
    // glTF v is down from the image's top; Prism's row 0 is the top too, so v is kept.
    int material = prim.material;
    if (const auto v = prim.extensions.find("KHR_materials_variants"); v != prim.extensions.end())
      material = variant_material(v->second, material, where + ".extensions.KHR_materials_variants");
    if (material >= static_cast<int>(scene_.materials.size()) || material < -1)
      throw SceneError(fmt::format("{}: material {} does not exist", where, material));
    if (material < 0) {
      if (default_material_ < 0) {
        Material d;
        d.name = "gltf-default";
        d.type = MaterialType::metallic_roughness;
        d.base_color = Vec3f(1.0f);
        d.metallic = 1.0f;
        d.roughness = 1.0f;
        scene_.materials.push_back(d);
        default_material_ = static_cast<int>(scene_.materials.size() - 1);
      }
      m.material = static_cast<std::uint32_t>(default_material_);
    } else {
      m.material = static_cast<std::uint32_t>(material);
    }
    const std::size_t dropped = check_and_clean_mesh(m, where);
    if (dropped) warnings_.push_back(fmt::format("glTF: {}: {} zero-area triangles dropped", where, dropped));
    if (m.indices.empty()) continue;
    // glTF 2.0 §3.7.2.1: without TANGENT, readers generate tangents (mesh_tangents.h).
    if (m.tangents.empty()) generate_tangents(m);
    scene_.meshes.push_back(std::move(m));
    created.push_back(static_cast<std::uint32_t>(scene_.meshes.size() - 1));
  }
  return meshes_[mesh_index] = std::move(created);
}

void GltfBuilder::visit_node(int node, const Transform& parent, int depth) {
  if (node < 0 || node >= static_cast<int>(model_.nodes.size())) fail(fmt::format("node {} does not exist", node));
  if (depth > kMaxNodeDepth) fail(fmt::format("the node hierarchy is deeper than {} (a cycle?)", kMaxNodeDepth));
  // glTF node hierarchies are forests (§3.5.2): a node reached twice has two parents or is
  // listed twice, which could otherwise make the traversal exponential.
  if (visited_.empty()) visited_.assign(model_.nodes.size(), false);
  if (visited_[node]) fail(fmt::format("node {} is reached twice (the node hierarchy must be a forest)", node));
  visited_[node] = true;
  const tinygltf::Node& n = model_.nodes[node];
  const Transform to_world = compose(parent, node_transform(n));
  if (!finite(to_world)) fail(fmt::format("nodes[{}]: the transform is not finite", node));
  if (n.mesh >= 0) {
    if (n.mesh >= static_cast<int>(model_.meshes.size())) fail(fmt::format("nodes[{}]: mesh {} does not exist", node, n.mesh));
    for (std::uint32_t m : mesh_primitives(n.mesh)) scene_.instances.push_back(Instance{m, to_world});
  }
  if (n.camera >= 0) {
    if (n.camera >= static_cast<int>(model_.cameras.size())) fail(fmt::format("nodes[{}]: camera {} does not exist", node, n.camera));
    add_camera(model_.cameras[n.camera], to_world, n.name.empty() ? fmt::format("camera{}", n.camera) : n.name);
  }
  if (const auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end() && it->second.Has("light")) {
    const auto& l = it->second.Get("light");
    if (!l.IsInt()) fail(fmt::format("nodes[{}]: KHR_lights_punctual.light is not an index", node));
    add_light(l.GetNumberAsInt(), to_world);
  }
  if (n.skin >= 0) warnings_.push_back(fmt::format("glTF: nodes[{}]: skinning ignored (bind pose used)", node));
  for (int child : n.children) visit_node(child, to_world, depth + 1);
}

void GltfBuilder::add_camera(const tinygltf::Camera& c, const Transform& to_world, const std::string& name) {
  if (c.type != "perspective") {
    warnings_.push_back(fmt::format("glTF: camera '{}' is {}: skipped (perspective only)", name, c.type));
    return;
  }
  const double yfov = c.perspective.yfov, aspect = c.perspective.aspectRatio;
  if (!(yfov > 0.0 && yfov < std::numbers::pi)) fail(fmt::format("camera '{}': yfov {} is out of range", name, yfov));
  Camera cam;
  cam.name = name;
  cam.eye = to_world.apply_point(Vec3f(0.0f));
  cam.target = to_world.apply_point(Vec3f(0.0f, 0.0f, -1.0f));
  cam.up = normalize(to_world.apply_vector(Vec3f(0.0f, 1.0f, 0.0f)));
  // glTF gives the vertical field of view; Prism's spans the shorter image axis.
  double fov = yfov;
  if (aspect > 0.0 && aspect < 1.0) fov = 2.0 * std::atan(aspect * std::tan(yfov / 2.0));
  cam.fov_degrees = static_cast<float>(fov * 180.0 / std::numbers::pi);
  if (scene_.cameras.empty() && aspect > 0.0 && std::isfinite(aspect)) {
    scene_.default_height = 512;
    scene_.default_width = std::clamp(static_cast<int>(std::lround(512.0 * aspect)), 1, 16384);
  }
  scene_.cameras.push_back(cam);
}

void GltfBuilder::add_light(int index, const Transform& to_world) {
  if (index < 0 || index >= static_cast<int>(model_.lights.size())) fail(fmt::format("light {} does not exist", index));
  const tinygltf::Light& l = model_.lights[index];
  Light light;
  light.name = l.name.empty() ? fmt::format("light{}", index) : l.name;
  if (l.color.size() == 3)
    light.color = Vec3f(static_cast<float>(l.color[0]), static_cast<float>(l.color[1]), static_cast<float>(l.color[2]));
  if (!is_finite(light.color) || min(light.color, Vec3f(0.0f)) != Vec3f(0.0f))
    fail(fmt::format("light {}: color components must be finite and ≥ 0", index));
  if (!(l.intensity >= 0.0) || !std::isfinite(l.intensity)) fail(fmt::format("light {}: intensity must be ≥ 0", index));
  // KHR_lights_punctual: the emitted light is color × intensity, intensity in candela
  // (point, spot) or lux (directional): Prism's intensity is the luminance of that product
  // (its colour is the chromaticity), so a darker colour is a dimmer light.
  light.intensity = static_cast<float>(l.intensity * relative_luminance(light.color, ColorPickerSpace::srgb));
  light.position = to_world.apply_point(Vec3f(0.0f));
  const Vec3f axis = to_world.apply_vector(Vec3f(0.0f, 0.0f, -1.0f));
  if (l.type == "point") {
    light.type = LightType::point;
  } else if (l.type == "spot" || l.type == "directional") {
    if (!(length(axis) > 0.0f)) fail(fmt::format("light {}: the node's transform is singular", index));
    light.direction = normalize(axis);
    light.type = l.type == "spot" ? LightType::spot : LightType::directional;
    if (l.type == "spot") {
      const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
      if (!(inner >= 0.0 && inner < outer && outer <= std::numbers::pi / 2))
        fail(fmt::format("light {}: spot cone angles must satisfy 0 ≤ inner < outer ≤ π/2", index));
      light.spot_inner_angle_degrees = static_cast<float>(inner * 180.0 / std::numbers::pi);
      light.spot_outer_angle_degrees = static_cast<float>(outer * 180.0 / std::numbers::pi);
    }
  } else {
    fail(fmt::format("light {}: unknown type '{}'", index, l.type));
  }
  if (l.range > 0.0) warnings_.push_back(fmt::format("glTF: light '{}': range ignored (inverse-square falloff)", light.name));
  scene_.lights.push_back(std::move(light));
}

// KHR_materials_variants: the file's variant names ({"variants": [{"name": ...}, ...]} at
// the top level), and the one LoadOptions::material_variant asks for.
void GltfBuilder::read_material_variants() {
  const auto it = model_.extensions.find("KHR_materials_variants");
  if (it == model_.extensions.end()) return;
  const std::string where = "extensions.KHR_materials_variants";
  const tinygltf::Value& variants = it->second.Get("variants");
  if (!variants.IsArray()) fail(where + ": 'variants' must be an array");
  for (std::size_t i = 0; i < variants.ArrayLen(); ++i) {
    const tinygltf::Value& name = variants.Get(static_cast<int>(i)).Get("name");
    if (!name.IsString()) fail(fmt::format("{}.variants[{}]: 'name' must be a string", where, i));
    scene_.material_variants.push_back(name.Get<std::string>());
  }
  const std::string& wanted = options_.material_variant;
  if (wanted.empty()) return;
  const auto& names = scene_.material_variants;
  const auto found = std::find(names.begin(), names.end(), wanted);
  if (found == names.end())
    throw UsageError(fmt::format("{}: no material variant '{}' (variants: {})", source_, wanted, fmt::join(names, ", ")));
  selected_variant_ = static_cast<int>(found - names.begin());
}

// A primitive's KHR_materials_variants mappings ([{"material": m, "variants": [v, ...]}]):
// the material of the mapping that lists the selected variant, else `material` (the
// primitive's own). Every mapping is checked, whichever variant is selected.
int GltfBuilder::variant_material(const tinygltf::Value& extension, int material, const std::string& where) const {
  const tinygltf::Value& mappings = extension.Get("mappings");
  if (!mappings.IsArray()) fail(where + ": 'mappings' must be an array");
  int chosen = material;
  for (std::size_t i = 0; i < mappings.ArrayLen(); ++i) {
    const tinygltf::Value& mapping = mappings.Get(static_cast<int>(i));
    const tinygltf::Value& mapped = mapping.Get("material");
    const tinygltf::Value& variants = mapping.Get("variants");
    if (!mapped.IsInt() || !variants.IsArray())
      fail(fmt::format("{}.mappings[{}]: needs an integer 'material' and an array 'variants'", where, i));
    for (std::size_t j = 0; j < variants.ArrayLen(); ++j) {
      const tinygltf::Value& v = variants.Get(static_cast<int>(j));
      if (!v.IsInt() || v.GetNumberAsInt() < 0 ||
          v.GetNumberAsInt() >= static_cast<int>(scene_.material_variants.size()))
        fail(fmt::format("{}.mappings[{}].variants[{}]: no such variant", where, i, j));
      if (v.GetNumberAsInt() == selected_variant_) chosen = mapped.GetNumberAsInt();
    }
  }
  return chosen;
}

Scene GltfBuilder::build() {
  check_extensions();
  read_material_variants();
  decode_images_in_parallel();
  build_materials();
  if (!model_.scenes.empty()) {
    const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (s >= static_cast<int>(model_.scenes.size())) fail(fmt::format("scene {} does not exist", s));
    for (int node : model_.scenes[s].nodes) visit_node(node, Transform{}, 0);
  } else {
    // No scene: every root node (one that is no node's child).
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const auto& n : model_.nodes)
      for (int c : n.children)
        if (c >= 0 && c < static_cast<int>(is_child.size())) is_child[c] = true;
    for (int i = 0; i < static_cast<int>(model_.nodes.size()); ++i)
      if (!is_child[i]) visit_node(i, Transform{}, 0);
  }
  if (scene_.instances.empty()) fail("the scene places no triangles");
  if (scene_.cameras.empty()) {
    scene_.camera = frame_scene_camera(scene_);
    scene_.camera.name = "default";
    scene_.cameras.push_back(scene_.camera);
  } else {
    scene_.camera = scene_.cameras.front();
  }
  scene_.warnings.insert(scene_.warnings.end(), warnings_.begin(), warnings_.end());
  validate_scene(scene_);
  return std::move(scene_);
}

Scene parse_gltf_scene(std::span<const unsigned char> bytes, std::string_view source,
                       const std::filesystem::path& scene_dir, const LoadOptions& options) {
  tinygltf::TinyGLTF loader;
  FileGuard guard;
  std::error_code ec;
  if (!scene_dir.empty()) guard.dir = std::filesystem::weakly_canonical(scene_dir, ec);
  guard.allow_external = options.allow_external_paths;
  guard.base = guard.dir.empty() ? std::string("/nonexistent-prism-scene-dir") : guard.dir.string();
  guard.where = fmt::format("{}: buffer or image uri", source);
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&file_exists, &expand_path, &guarded_read, &no_write, &guard});
  loader.SetImageLoader(&keep_image_bytes, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const std::string& base = guard.base;
  const bool binary = bytes.size() >= 4 && std::string_view(reinterpret_cast<const char*>(bytes.data()), 4) == "glTF";
  if (bytes.size() > 0x7fffffffu) throw SceneError(fmt::format("{}: the file is too large", source));
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                       static_cast<unsigned int>(bytes.size()), base)
                         : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                      static_cast<unsigned int>(bytes.size()), base);
  // tinygltf reads `asset` first: a file of another major version is reported as such,
  // whatever else went wrong with it, and a refused uri rather than "File not found".
  if (!model.asset.version.empty() || ok) check_gltf_version(model.asset, source);
  if (!guard.refusal.empty()) throw SceneError(guard.refusal);
  if (!ok || !err.empty()) {
    std::string message = err.empty() ? std::string("malformed glTF") : err;
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    throw SceneError(fmt::format("{}: {}", source, message));
  }
  GltfBuilder builder(model, std::string(source), guard.dir, options);
  Scene scene = builder.build();
  scene.name = std::filesystem::path(source).stem().string();
  return scene;
}

Scene load_gltf_scene(const std::filesystem::path& path, const LoadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("cannot read glTF scene '{}'", path.string()));
  std::vector<unsigned char> bytes;
  if (!read_to_end(in, regular_file_size_or_zero(path), bytes))
    throw IoError(fmt::format("cannot read glTF scene '{}'", path.string()));
  std::error_code ec;
  return parse_gltf_scene(bytes, path.filename().string(), std::filesystem::absolute(path, ec).parent_path(), options);
}

}  // namespace prism::loaders
