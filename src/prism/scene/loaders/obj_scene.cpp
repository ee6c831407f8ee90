#include "prism/scene/loaders/obj_scene.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tiny_obj_loader.h>

#include "prism/core/error.h"
#include "prism/scene/loaders/mesh_checks.h"
#include "prism/scene/loaders/mtl_material.h"
#include "prism/scene/loaders/path_safety.h"
#include "prism/scene/loaders/scene_camera.h"

namespace prism::loaders {
namespace {

// Opens `mtllib` names through the scene's path rules instead of tinyobjloader's own file
// access, and remembers the first refusal to report it as an error.
class SafeMaterialReader : public tinyobj::MaterialReader {
 public:
  SafeMaterialReader(const ObjContext& context, std::string_view source) : context_(context), source_(source) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warn, std::string* err) override {
    std::string text;
    if (context_.mtl_text) {
      text = *context_.mtl_text;
    } else {
      try {
        const std::filesystem::path path =
            resolve_scene_reference(context_.dir, name, context_.options.allow_external_paths,
                                    fmt::format("{}: mtllib", source_));
        std::ifstream in(path, std::ios::binary);
        if (!in) throw IoError(fmt::format("{}: cannot read material library '{}'", source_, name));
        std::ostringstream s;
        s << in.rdbuf();
        text = s.str();
      } catch (const Error& e) {
        if (!failure_) failure_ = std::current_exception();
        if (err) *err += e.what();
        return false;
      }
    }
    std::istringstream in(text);
    tinyobj::LoadMtl(names, materials, &in, warn, err);
    return true;
  }

  void rethrow_failure() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  const ObjContext& context_;
  std::string source_;
  std::exception_ptr failure_;
};

struct VertexKey {
  int v, vt, vn;
  auto operator<=>(const VertexKey&) const = default;
};

struct MeshUnderConstruction {
  TriangleMesh mesh;
  std::map<VertexKey, std::uint32_t> vertices;
  bool missing_uvs = false, missing_normals = false;
};

// Builds one mesh per (shape, material) from tinyobjloader's corner-indexed faces, creating
// a vertex per distinct (position, uv, normal) triple.
class MeshBuilder {
 public:
  MeshBuilder(const tinyobj::attrib_t& attrib, std::string_view source) : attrib_(attrib), source_(source) {}

  void add_face_corner(MeshUnderConstruction& m, const tinyobj::index_t& i, std::string_view where) {
    TriangleMesh& mesh = m.mesh;
    auto& vertices = m.vertices;
    const VertexKey key{i.vertex_index, i.texcoord_index, i.normal_index};
    if (const auto it = vertices.find(key); it != vertices.end()) {
      mesh.indices.push_back(it->second);
      return;
    }
    const std::size_t positions = attrib_.vertices.size() / 3, uvs = attrib_.texcoords.size() / 2,
                      normals = attrib_.normals.size() / 3;
    if (i.vertex_index < 0 || static_cast<std::size_t>(i.vertex_index) >= positions)
      throw SceneError(fmt::format("{}: {}: vertex index {} is out of range (the file has {} vertices)", source_, where,
                                   i.vertex_index + 1, positions));
    if (i.texcoord_index >= 0 && static_cast<std::size_t>(i.texcoord_index) >= uvs)
      throw SceneError(fmt::format("{}: {}: texture coordinate index {} is out of range (the file has {})", source_,
                                   where, i.texcoord_index + 1, uvs));
    if (i.normal_index >= 0 && static_cast<std::size_t>(i.normal_index) >= normals)
      throw SceneError(fmt::format("{}: {}: normal index {} is out of range (the file has {})", source_, where,
                                   i.normal_index + 1, normals));
    const float* p = &attrib_.vertices[3 * static_cast<std::size_t>(i.vertex_index)];
    mesh.positions.emplace_back(p[0], p[1], p[2]);
    // OBJ's v runs bottom to top; Prism's (glTF's) top to bottom.
    if (i.texcoord_index >= 0) {
      const float* t = &attrib_.texcoords[2 * static_cast<std::size_t>(i.texcoord_index)];
      mesh.uvs.emplace_back(t[0], 1.0f - t[1]);
    } else {
      mesh.uvs.emplace_back(0.0f, 0.0f);
      m.missing_uvs = true;
    }
    if (i.normal_index >= 0) {
      const float* n = &attrib_.normals[3 * static_cast<std::size_t>(i.normal_index)];
      mesh.normals.emplace_back(n[0], n[1], n[2]);
    } else {
      mesh.normals.emplace_back(0.0f, 0.0f, 0.0f);
      m.missing_normals = true;
    }
    const auto index = static_cast<std::uint32_t>(mesh.positions.size() - 1);
    vertices.emplace(key, index);
    mesh.indices.push_back(index);
  }

  // Attributes given for only some corners cannot be per-vertex: drop them for the mesh.
  static void finish(MeshUnderConstruction& m) {
    TriangleMesh& mesh = m.mesh;
    if (m.missing_uvs) mesh.uvs.clear();
    if (m.missing_normals) mesh.normals.clear();
    for (Vec3f& n : mesh.normals) {
      const float len = length(n);
      if (len > 0.0f && std::isfinite(len)) n = n / len;
    }
  }

 private:
  const tinyobj::attrib_t& attrib_;
  std::string source_;
};

// The image is decoded with the others at the end of the load (texture_cache.h); an error
// decoding it names the material and map that asked for it, then the file.
// MTL's -s (scale) and -o (origin offset) of the texture coordinates become the texture's
// own (a copy of the image, as pbrt-v4's uscale/udelta do): uv_t = s·uv + o in the OBJ's
// upward v, as three.js's MTLLoader (repeat = s, offset = o) and Blender's importer read them.
int load_material_texture(const ObjContext& context, const std::string& name, TextureEncoding encoding,
                          const tinyobj::texture_option_t& option, const std::string& where,
                          TextureCache::ImageCheck check = {}) {
  const std::filesystem::path path =
      resolve_scene_reference(context.dir, name, context.options.allow_external_paths, where);
  const TextureWrap wrap = option.clamp ? TextureWrap::clamp : TextureWrap::repeat;
  const int index = context.textures->load(path, encoding, wrap, wrap, where, std::move(check));
  const float su = option.scale[0], sv = option.scale[1], ou = option.origin_offset[0], ov = option.origin_offset[1];
  if (su == 1.0f && sv == 1.0f && ou == 0.0f && ov == 0.0f) return index;
  if (!std::isfinite(su) || !std::isfinite(sv) || !std::isfinite(ou) || !std::isfinite(ov))
    throw SceneError(fmt::format("{}: -s and -o must be finite numbers", where));
  return context.textures->add_with_uv_transform(index, su, sv, ou, ov);
}

std::vector<std::uint32_t> add_materials(Scene& scene, const std::vector<tinyobj::material_t>& materials,
                                         std::string_view source, const ObjContext& context) {
  std::vector<std::uint32_t> indices;
  std::vector<std::string> ignored;
  for (const auto& mtl : materials) {
    Material m = material_from_mtl(mtl, ignored);
    const std::string where = fmt::format("{}: material '{}'", source, mtl.name);
    if (!mtl.diffuse_texname.empty() || !mtl.emissive_texname.empty() || !mtl.bump_texname.empty() ||
        !mtl.normal_texname.empty()) {
      if (!context.textures) {
        ignored.push_back("map_Kd/map_Ke/bump/norm (no texture support here)");
      } else {
        if (!mtl.diffuse_texname.empty())
          m.base_color_texture = load_material_texture(context, mtl.diffuse_texname, TextureEncoding::srgb,
                                                       mtl.diffuse_texopt, where + " map_Kd");
        if (!mtl.emissive_texname.empty())
          m.emission.texture = load_material_texture(context, mtl.emissive_texname, TextureEncoding::srgb,
                                                     mtl.emissive_texopt, where + " map_Ke");
        // bump / map_Bump: heights (linear data) times its -bm multiplier, in scene units.
        if (!mtl.bump_texname.empty()) {
          m.bump_texture = load_material_texture(context, mtl.bump_texname, TextureEncoding::linear, mtl.bump_texopt,
                                                 where + " bump");
          const float multiplier = mtl.bump_texopt.bump_multiplier;
          m.bump_scale = std::isfinite(multiplier) ? multiplier : 1.0f;
        }
        // norm: a tangent-space normal map, +y up the image (glTF's convention).
        if (!mtl.normal_texname.empty()) {
          m.normal_texture = load_material_texture(
              context, mtl.normal_texname, TextureEncoding::linear, mtl.normal_texopt, where + " norm",
              [where](const TextureImage& image) {
                if (image.channels < 3)
                  throw SceneError(fmt::format("{} norm: a normal map needs an RGB image", where));
              });
        }
      }
    }
    indices.push_back(static_cast<std::uint32_t>(scene.materials.size()));
    scene.materials.push_back(std::move(m));
  }
  std::sort(ignored.begin(), ignored.end());
  ignored.erase(std::unique(ignored.begin(), ignored.end()), ignored.end());
  if (!ignored.empty())
    scene.warnings.push_back(fmt::format("{}: MTL parameters ignored: {}", source, fmt::join(ignored, ", ")));
  return indices;
}

// The OBJ text with tinyobjloader's skin-weight lines (`vw`, its own extension) turned into
// comments: Prism has no skinning, and Debian's tinyobjloader converts their joint ids to int
// unchecked (UBSan: inf outside the range of int, found by the fuzz_obj target). Lines are
// found as tinyobjloader finds them — ending at '\n' or '\r', leading spaces and tabs
// skipped — and keep their length, so line numbers in messages do not move.
std::string without_skin_weight_lines(std::string_view obj_text) {
  std::string text(obj_text);
  bool line_start = true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      line_start = true;
      continue;
    }
    if (!line_start) continue;
    if (c == ' ' || c == '\t') continue;
    line_start = false;
    if (c == 'v' && i + 2 < text.size() && text[i + 1] == 'w' && (text[i + 2] == ' ' || text[i + 2] == '\t')) {
      text[i] = '#';
      text[i + 1] = ' ';
    }
  }
  return text;
}

}  // namespace

std::vector<std::uint32_t> append_obj(Scene& scene, std::string_view obj_text, std::string_view source,
                                      const ObjContext& context, std::optional<std::uint32_t> material_override) {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream in{without_skin_weight_lines(obj_text)};
  SafeMaterialReader reader(context, source);
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &reader, true, false);
  reader.rethrow_failure();
  if (!ok) throw SceneError(fmt::format("{}: malformed OBJ: {}", source, err.empty() ? "parse failed" : err));

  std::vector<std::uint32_t> material_indices;
  if (!material_override) material_indices = add_materials(scene, materials, source, context);
  std::optional<std::uint32_t> default_material = material_override;
  const auto material_for = [&](int id) {
    if (id >= 0 && static_cast<std::size_t>(id) < material_indices.size()) return material_indices[id];
    if (!default_material) {
      Material m;
      m.name = fmt::format("{}:default", source);
      default_material = static_cast<std::uint32_t>(scene.materials.size());
      scene.materials.push_back(std::move(m));
    }
    return *default_material;
  };

  std::vector<std::uint32_t> added;
  std::size_t dropped = 0;
  MeshBuilder builder(attrib, source);
  for (const tinyobj::shape_t& shape : shapes) {
    // Faces grouped by material, each group one mesh.
    std::map<std::uint32_t, MeshUnderConstruction> by_material;
    std::size_t corner = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t n = shape.mesh.num_face_vertices[f];
      const int mat_id = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      MeshUnderConstruction& building = by_material[material_for(mat_id)];
      const std::string where = fmt::format("object '{}', face {}", shape.name, f + 1);
      if (n != 3 || corner + n > shape.mesh.indices.size())
        throw SceneError(fmt::format("{}: {}: malformed face", source, where));
      for (std::size_t k = 0; k < n; ++k) builder.add_face_corner(building, shape.mesh.indices[corner + k], where);
      corner += n;
    }
    for (auto& [material, entry] : by_material) {
      MeshBuilder::finish(entry);
      TriangleMesh& mesh = entry.mesh;
      mesh.material = material;
      mesh.name = shape.name.empty() ? fmt::format("{}#{}", source, scene.meshes.size()) : shape.name;
      dropped += check_and_clean_mesh(mesh, fmt::format("{}: object '{}'", source, shape.name));
      if (mesh.indices.empty()) continue;
      added.push_back(static_cast<std::uint32_t>(scene.meshes.size()));
      scene.meshes.push_back(std::move(mesh));
    }
  }
  if (dropped > 0) scene.warnings.push_back(fmt::format("{}: dropped {} zero-area triangles", source, dropped));
  if (!warn.empty()) {
    std::string first_line = warn.substr(0, warn.find('\n'));
    scene.warnings.push_back(fmt::format("{}: {}", source, first_line));
  }
  return added;
}

Scene load_obj_scene(const std::filesystem::path& path, const LoadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("cannot read scene '{}': cannot open it", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene;
  scene.name = path.stem().string();
  TextureCache textures(scene, options);
  ObjContext context;
  context.dir = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  context.options = options;
  context.textures = &textures;
  try {
    append_obj(scene, text.str(), path.string(), context);
    textures.finish();
  } catch (...) {
    textures.rethrow_first_error(std::current_exception());
  }
  if (scene.meshes.empty()) throw SceneError(fmt::format("{}: the file has no triangles", path.string()));
  bool emissive = false;
  for (const auto& m : scene.materials) emissive = emissive || m.is_emissive();
  if (!emissive) scene.warnings.push_back(fmt::format("{}: no emissive material (Ke): the scene has no light", path.string()));
  scene.camera = frame_scene_camera(scene);
  scene.cameras.push_back(scene.camera);
  validate_scene(scene);
  return scene;
}

}  // namespace prism::loaders
