// pbrt-v4 shapes → triangle meshes: trianglemesh, plymesh, bilinearmesh and sphere.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/mesh_checks.h"
#include "prism/scene/loaders/pbrt_builder.h"
#include "prism/scene/loaders/ply_mesh.h"
#include "prism/scene/loaders/sphere_mesh.h"

namespace prism::loaders {
namespace {

constexpr double kMaxIndex = 4294967295.0;

std::vector<Vec3f> read_vec3s(const PbrtParams& p, std::string_view name) {
  const auto v = p.get_numbers(name);
  if (v.size() % 3 != 0) p.fail(*p.find(name), "the number of values is not a multiple of 3");
  std::vector<Vec3f> out(v.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = Vec3f(static_cast<float>(v[3 * i]), static_cast<float>(v[3 * i + 1]), static_cast<float>(v[3 * i + 2]));
  return out;
}

std::vector<Vec2f> read_vec2s(const PbrtParams& p, std::string_view name) {
  const auto v = p.get_numbers(name);
  if (v.size() % 2 != 0) p.fail(*p.find(name), "the number of values is not a multiple of 2");
  std::vector<Vec2f> out(v.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec2f(static_cast<float>(v[2 * i]), static_cast<float>(v[2 * i + 1]));
  return out;
}

std::vector<std::uint32_t> read_indices(const PbrtParams& p, std::string_view name, std::size_t vertex_count) {
  const auto v = p.get_numbers(name);
  std::vector<std::uint32_t> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] < 0 || v[i] > kMaxIndex || v[i] != std::floor(v[i]) || v[i] >= static_cast<double>(vertex_count))
      p.fail(*p.find(name), fmt::format("index {} ({}) is out of range for {} vertices", i, v[i], vertex_count));
    out[i] = static_cast<std::uint32_t>(v[i]);
  }
  return out;
}

double transformed_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vec3f& a = mesh.positions[mesh.indices[t]];
    area += 0.5 * length(cross(mesh.positions[mesh.indices[t + 1]] - a, mesh.positions[mesh.indices[t + 2]] - a));
  }
  return area;
}

}  // namespace

void PbrtBuilder::shape(const std::string& type, const PbrtParams& p) {
  TriangleMesh mesh;
  mesh.name = fmt::format("{}-{}", type, p.line);
  if (type == "trianglemesh" || type == "bilinearmesh") {
    mesh.positions = read_vec3s(p, "P");
    if (mesh.positions.empty()) p.fail(PbrtParam{"point3", "P", {}, {}, p.line}, "missing or empty");
    mesh.normals = read_vec3s(p, "N");
    mesh.uvs = read_vec2s(p, "uv");
    auto indices = read_indices(p, "indices", mesh.positions.size());
    if (type == "trianglemesh") {
      if (indices.empty() && mesh.positions.size() == 3) indices = {0, 1, 2};
      if (indices.empty() || indices.size() % 3 != 0)
        throw SceneError(fmt::format("{}:{}: trianglemesh: \"indices\" must hold a multiple of 3 values", p.source, p.line));
      mesh.indices = std::move(indices);
    } else {
      if (indices.empty() && mesh.positions.size() == 4) indices = {0, 1, 2, 3};
      if (indices.empty() || indices.size() % 4 != 0)
        throw SceneError(fmt::format("{}:{}: bilinearmesh: \"indices\" must hold a multiple of 4 values", p.source, p.line));
      // pbrt's patch corners are p00 p10 p01 p11; split along p00–p11 keeping the u×v normal.
      for (std::size_t q = 0; q < indices.size(); q += 4)
        mesh.indices.insert(mesh.indices.end(), {indices[q], indices[q + 1], indices[q + 3], indices[q], indices[q + 3], indices[q + 2]});
    }
    for (const char* n : {"S", "faceIndices", "emissionfilename"}) p.find(n);
  } else if (type == "plymesh") {
    const std::string file = p.get_string("filename", "");
    if (file.empty()) throw SceneError(fmt::format("{}:{}: plymesh needs a \"filename\"", p.source, p.line));
    PlyMesh ply;
    try {
      ply = read_ply_mesh(resolve(p, "filename", file));
    } catch (const IoError& e) {
      throw IoError(fmt::format("{}:{}: plymesh: {}", p.source, p.line, e.what()));
    } catch (const SceneError& e) {
      throw SceneError(fmt::format("{}:{}: plymesh: {}", p.source, p.line, e.what()));
    }
    mesh.positions = std::move(ply.positions);
    mesh.normals = std::move(ply.normals);
    mesh.uvs = std::move(ply.uvs);
    mesh.indices = std::move(ply.indices);
    mesh.name = file;
    if (p.has("displacement")) ignore("plymesh displacement", p);
  } else if (type == "sphere") {
    const double radius = p.get_float("radius", 1.0);
    if (!(radius > 0.0) || radius > 1e30) p.fail(*p.find("radius"), "must be positive");
    if (p.has("zmin") || p.has("zmax") || p.has("phimax")) ignore("partial sphere (zmin/zmax/phimax): full sphere used", p);
    mesh = make_uv_sphere(Vec3f(0.0f), static_cast<float>(radius), 48);
    mesh.name = fmt::format("sphere-{}", p.line);
    // make_uv_sphere's poles lie on ±y; pbrt's on ±z. Rotate so uvs follow pbrt's layout.
    for (auto* v : {&mesh.positions, &mesh.normals})
      for (Vec3f& x : *v) x = Vec3f(x.x, -x.z, x.y);
  } else {
    ignore(fmt::format("Shape \"{}\"", type), p);
    for (const auto& param : p.params) param.used = true;
    return;
  }
  // pbrt-v4 looks images up at t = 1 − v (v up the image); Prism's v points down it.
  if (type != "sphere")
    for (Vec2f& uv : mesh.uvs) uv.y = 1.0f - uv.y;
  add_mesh(std::move(mesh), p, !p.has("N") ? false : true);
}

void PbrtBuilder::add_mesh(TriangleMesh mesh, const PbrtParams& p, bool) {
  if (!state_.ctm.is_affine()) throw SceneError(fmt::format("{}:{}: Shape: the transform is projective", p.source, p.line));
  const Transform t = state_.ctm.to_transform();
  const auto inverse = state_.ctm.inverse();
  if (!inverse) throw SceneError(fmt::format("{}:{}: Shape: the transform is singular", p.source, p.line));
  for (Vec3f& x : mesh.positions) x = t.apply_point(x);
  const Transform inv = inverse->to_transform();
  for (Vec3f& n : mesh.normals) {  // normals transform by the inverse transpose
    n = Vec3f(inv.m[0][0] * n.x + inv.m[1][0] * n.y + inv.m[2][0] * n.z,
              inv.m[0][1] * n.x + inv.m[1][1] * n.y + inv.m[2][1] * n.z,
              inv.m[0][2] * n.x + inv.m[1][2] * n.y + inv.m[2][2] * n.z);
    const float l = length(n);
    if (l > 0.0f) n = n / l;
  }
  // pbrt's front side: the winding normal, flipped by ReverseOrientation and by a
  // handedness-swapping transform, then turned towards the shading normals when given.
  const bool flip = state_.reverse_orientation != (state_.ctm.determinant3() < 0.0);
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    bool f = flip;
    if (!mesh.normals.empty() && mesh.normals.size() == mesh.positions.size()) {
      const Vec3f& a = mesh.positions[mesh.indices[i]];
      const Vec3f ng = cross(mesh.positions[mesh.indices[i + 1]] - a, mesh.positions[mesh.indices[i + 2]] - a);
      const Vec3f ns = mesh.normals[mesh.indices[i]] + mesh.normals[mesh.indices[i + 1]] + mesh.normals[mesh.indices[i + 2]];
      f = dot(ng, ns) < 0.0f;
      if (state_.reverse_orientation) f = !f;
    }
    if (f) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  }
  const std::size_t dropped = check_and_clean_mesh(mesh, fmt::format("{}:{}: Shape", p.source, p.line));
  (void)dropped;
  if (mesh.indices.empty()) {
    ignore("Shape with only degenerate triangles", p);
    return;
  }
  mesh.material = shape_material(p, state_.area_light && state_.area_light->power ? transformed_area(mesh) : 0.0);
  mesh.material = alpha_material(mesh.material, p);
  note_unused(fmt::format("Shape \"{}\"", mesh.name), p);
  scene_.meshes.push_back(std::move(mesh));
  const auto index = static_cast<std::uint32_t>(scene_.meshes.size() - 1);
  if (current_object_) {
    if (state_.area_light) ignore("AreaLightSource inside ObjectBegin (not emissive)", p);
    objects_[*current_object_].push_back(index);
  } else {
    world_meshes_.push_back(index);
  }
}

std::uint32_t PbrtBuilder::shape_material(const PbrtParams& p, double area) {
  if (state_.material < 0) {
    if (default_material_ < 0) {
      Material m;
      m.name = "pbrt-default";
      m.base_color = Vec3f(0.5f);
      scene_.materials.push_back(m);
      default_material_ = static_cast<int>(scene_.materials.size() - 1);
    }
    state_.material = default_material_;
  }
  const std::uint32_t material = with_interior_medium(static_cast<std::uint32_t>(state_.material), p);
  if (!state_.area_light || current_object_) return material;
  const PbrtAreaLight& light = *state_.area_light;
  const auto key = std::make_pair(static_cast<int>(material), area_light_id_);
  if (!light.power) {
    if (const auto it = emissive_materials_.find(key); it != emissive_materials_.end()) return it->second;
  }
  Material m = scene_.materials[material];
  m.name += "+light";
  m.emission.color = light.color;
  m.emission.color_space = light.color_space;
  m.emission.spectrum = light.spectrum;
  m.emission.luminance_nits = light.luminance_nits;
  m.emission.two_sided = light.two_sided;
  if (light.power) {
    // Φ = π L A per emitting side (Lambertian), so L = Φ / (π A sides).
    const double sides = light.two_sided ? 2.0 : 1.0;
    if (!(area > 0.0)) throw SceneError(fmt::format("{}:{}: area light with \"power\" on a shape of zero area", p.source, p.line));
    m.emission.luminance_nits = static_cast<float>(*light.power / (std::numbers::pi * area * sides));
  }
  scene_.materials.push_back(std::move(m));
  const auto index = static_cast<std::uint32_t>(scene_.materials.size() - 1);
  if (!light.power) emissive_materials_[key] = index;
  return index;
}

}  // namespace prism::loaders
