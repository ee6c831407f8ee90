// prism-scene/1: meshes (inline arrays, OBJ files, generated spheres), transforms and instances.
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/loaders/json_scene_reader.h"
#include "prism/scene/loaders/mesh_checks.h"
#include "prism/scene/loaders/obj_scene.h"
#include "prism/scene/loaders/sphere_mesh.h"

namespace prism::loaders {
namespace {

// Rodrigues' rotation about a unit axis.
Transform rotation(Vec3f axis, float degrees) {
  const float a = degrees * std::numbers::pi_v<float> / 180.0f, c = std::cos(a), s = std::sin(a), t = 1.0f - c;
  axis = normalize(axis);
  const float x = axis.x, y = axis.y, z = axis.z;
  Transform r;
  const float m[3][3] = {{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
                         {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
                         {t * x * z - s * y, t * y * z + s * x, t * z * z + c}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][j];
  return r;
}

// Flat [x0, y0, z0, x1, ...] or nested [[x0, y0, z0], ...] arrays of N-vectors, read an
// element at a time (a JsonValue per number of a million-triangle mesh was 200 MB).
template <int N>
std::vector<std::array<float, N>> read_vectors(const JsonValue& value) {
  const std::size_t count = value.size();
  std::vector<std::array<float, N>> out;
  if (value.is_array_of_arrays()) {
    out.reserve(count);
    value.for_each_element([&](const JsonValue& e) {
      if (e.size(N) != N) e.fail(fmt::format("expected {} numbers", N));
      std::array<float, N> v;
      int k = 0;
      e.for_each_element([&](const JsonValue& c) { v[static_cast<std::size_t>(k++)] = c.as_float(); });
      out.push_back(v);
    });
    return out;
  }
  if (count % N != 0) value.fail(fmt::format("expected a multiple of {} numbers, found {}", N, count));
  out.reserve(count / N);
  std::array<float, N> v;
  int k = 0;
  value.for_each_element([&](const JsonValue& c) {
    v[static_cast<std::size_t>(k++)] = c.as_float();
    if (k == N) {
      out.push_back(v);
      k = 0;
    }
  });
  return out;
}

void read_inline_arrays(TriangleMesh& mesh, const JsonValue& value) {
  for (const auto& p : read_vectors<3>(value["positions"])) mesh.positions.emplace_back(p[0], p[1], p[2]);
  const JsonValue indices = value["indices"];
  mesh.indices.reserve(indices.size());
  indices.for_each_element([&](const JsonValue& i) {
    mesh.indices.push_back(static_cast<std::uint32_t>(i.as_integer(0, std::numeric_limits<std::uint32_t>::max())));
  });
  if (auto n = value.find("normals"))
    for (const auto& v : read_vectors<3>(*n)) mesh.normals.emplace_back(v[0], v[1], v[2]);
  if (auto u = value.find("uvs"))
    for (const auto& v : read_vectors<2>(*u)) mesh.uvs.emplace_back(v[0], v[1]);
}

// Bakes a transform into the vertices: points by the affine map, normals by the inverse
// transpose of its linear part (computed as the cofactor matrix, which differs only by
// the determinant's scale and sign; the normals are renormalised).
void bake_transform(TriangleMesh& mesh, const Transform& t) {
  for (Vec3f& p : mesh.positions) p = t.apply_point(p);
  const auto& m = t.m;
  Transform cofactor;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      cofactor.m[i][j] = m[(i + 1) % 3][(j + 1) % 3] * m[(i + 2) % 3][(j + 2) % 3] -
                         m[(i + 1) % 3][(j + 2) % 3] * m[(i + 2) % 3][(j + 1) % 3];
  const float det = m[0][0] * cofactor.m[0][0] + m[0][1] * cofactor.m[0][1] + m[0][2] * cofactor.m[0][2];
  for (Vec3f& n : mesh.normals) {
    const Vec3f tn = cofactor.apply_vector(n) * (det < 0.0f ? -1.0f : 1.0f);
    const float len = length(tn);
    n = len > 0.0f ? tn / len : n;
  }
  // A mirroring transform turns counter-clockwise into clockwise: keep the front face.
  if (det < 0.0f)
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

}  // namespace

Transform read_transform(const JsonValue& value) {
  value.expect_keys({"translate", "rotate", "rotate_degrees", "scale", "matrix"});
  Transform t;
  if (auto m = value.find("matrix")) {
    const auto e = m->elements(16);
    if (e.size() != 12 && e.size() != 16) m->fail("expected 12 or 16 numbers (row-major 3×4 or 4×4)");
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) t.m[i][j] = e[4 * i + j].as_float();
      t.translation[i] = e[4 * i + 3].as_float();
    }
    if (e.size() == 16 && (e[12].as_float() != 0 || e[13].as_float() != 0 || e[14].as_float() != 0 || e[15].as_float() != 1))
      m->fail("the last row must be [0, 0, 0, 1] (projective transforms are not supported)");
  }
  if (auto s = value.find("scale")) {
    const Vec3f v = s->is_number() ? Vec3f(s->as_float()) : s->as_vec3();
    if (v.x == 0.0f || v.y == 0.0f || v.z == 0.0f) s->fail("scale factors must not be zero");
    t = compose(Transform::scale(v), t);
  }
  if (auto r = value.find("rotate")) {
    r->expect_keys({"axis", "angle_degrees"});
    const Vec3f axis = (*r)["axis"].as_vec3();
    if (!(length(axis) > 0.0f)) (*r)["axis"].fail("expected a non-zero axis");
    t = compose(rotation(axis, (*r)["angle_degrees"].as_float()), t);
  }
  if (auto r = value.find("rotate_degrees")) {  // about x, then y, then z
    const Vec3f a = r->as_vec3();
    t = compose(rotation({0, 0, 1}, a.z), compose(rotation({0, 1, 0}, a.y), compose(rotation({1, 0, 0}, a.x), t)));
  }
  if (auto tr = value.find("translate")) t = compose(Transform::translate(tr->as_vec3()), t);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(t.m[i][j])) value.fail("the transform is not finite");
  return t;
}

void JsonSceneReader::read_mesh(const JsonValue& value) {
  value.expect_keys({"name", "material", "positions", "indices", "normals", "uvs", "file", "shape", "center", "radius",
                     "subdivisions", "transform", "prototype"});
  const std::string name = value.get_string("name", fmt::format("mesh{}", mesh_indices.size()));
  if (mesh_indices.contains(name)) value["name"].fail(fmt::format("mesh '{}' is defined twice", name));
  const std::string where = fmt::format("{}: {} '{}'", document.source, value.path(), name);
  std::vector<TriangleMesh> built;
  if (auto file = value.find("file")) {
    if (value.has("positions") || value.has("shape")) value.fail("give one of 'positions', 'file' and 'shape'");
    const std::filesystem::path path = resolve(*file);
    std::ifstream in(path, std::ios::binary);
    if (!in) file->fail(fmt::format("cannot read '{}'", path.string()));
    std::ostringstream text;
    text << in.rdbuf();
    // The OBJ's own references (mtllib, map_Kd) resolve against, and may not leave, its folder.
    const ObjContext context{path.parent_path(), options, &textures, nullptr};
    std::optional<std::uint32_t> override_material;
    if (auto m = value.find("material")) override_material = material_index(*m);
    const std::size_t first = scene.meshes.size();
    append_obj(scene, text.str(), path.string(), context, override_material);
    std::vector<std::uint32_t> added;
    for (std::size_t i = first; i < scene.meshes.size(); ++i) added.push_back(static_cast<std::uint32_t>(i));
    if (added.empty()) file->fail("the OBJ file has no triangles");
    if (auto t = value.find("transform")) {
      const Transform tr = read_transform(*t);
      for (std::uint32_t i : added) bake_transform(scene.meshes[i], tr);
    }
    const bool prototype = value.get_bool("prototype", false);
    mesh_is_prototype.resize(scene.meshes.size(), prototype);
    mesh_indices.emplace(name, std::move(added));
    return;
  }
  TriangleMesh mesh;
  mesh.name = name;
  mesh.material = material_index(value["material"]);
  if (auto shape = value.find("shape")) {
    if (value.has("positions")) value.fail("give one of 'positions', 'file' and 'shape'");
    enum class Shape { sphere };
    shape->as_enum<Shape>({{"sphere", Shape::sphere}});
    const Vec3f center = value.get_vec3("center", Vec3f(0.0f));
    const float radius = value["radius"].as_float(1e-9f, 1e12f);
    // 512 rings is 0.5 M triangles: enough for any sphere a scene file would want.
    const int rings = value.has("subdivisions") ? static_cast<int>(value["subdivisions"].as_integer(2, 512)) : 32;
    TriangleMesh sphere = make_uv_sphere(center, radius, rings);
    mesh.positions = std::move(sphere.positions);
    mesh.indices = std::move(sphere.indices);
    mesh.normals = std::move(sphere.normals);
    mesh.uvs = std::move(sphere.uvs);
  } else {
    read_inline_arrays(mesh, value);
  }
  const std::size_t dropped = check_and_clean_mesh(mesh, where);
  if (dropped > 0) scene.warnings.push_back(fmt::format("{}: dropped {} zero-area triangles", where, dropped));
  if (auto t = value.find("transform")) bake_transform(mesh, read_transform(*t));
  if (mesh.indices.empty()) {  // nothing to place: instances of it place nothing
    scene.warnings.push_back(fmt::format("{}: no triangles", where));
    mesh_indices.emplace(name, std::vector<std::uint32_t>{});
    return;
  }
  mesh_indices.emplace(name, std::vector<std::uint32_t>{static_cast<std::uint32_t>(scene.meshes.size())});
  mesh_is_prototype.push_back(value.get_bool("prototype", false));
  scene.meshes.push_back(std::move(mesh));
}

void JsonSceneReader::read_instance(const JsonValue& value) {
  value.expect_keys({"mesh", "transform"});
  const JsonValue name = value["mesh"];
  const auto it = mesh_indices.find(name.as_string());
  if (it == mesh_indices.end()) name.fail(fmt::format("no mesh named '{}'", name.as_string()));
  const Transform t = value.has("transform") ? read_transform(value["transform"]) : Transform{};
  for (std::uint32_t mesh : it->second) scene.instances.push_back({mesh, t});
}

}  // namespace prism::loaders
