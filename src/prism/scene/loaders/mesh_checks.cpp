#include "prism/scene/loaders/mesh_checks.h"

#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism::loaders {
namespace {

template <typename V>
void check_finite(const std::vector<V>& values, std::string_view what, std::string_view where) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    bool finite = true;
    for (std::size_t k = 0; k < sizeof(V) / sizeof(float); ++k) finite = finite && std::isfinite(values[i][k]);
    if (!finite) throw SceneError(fmt::format("{}: {} {} is not finite (NaN or infinity)", where, what, i));
  }
}

// Zero area in the precision the positions carry: the cross product's length is tiny
// compared to the squared longest edge (a sliver thinner than float rounding).
bool has_zero_area(const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  const Vec3d pa(a), pb(b), pc(c);
  const Vec3d e0 = pb - pa, e1 = pc - pa, e2 = pc - pb;
  const double twice_area = length(cross(e0, e1));
  const double longest_squared = std::max({length_squared(e0), length_squared(e1), length_squared(e2)});
  return !(twice_area > 1e-12 * longest_squared);
}

}  // namespace

std::size_t check_and_clean_mesh(TriangleMesh& mesh, std::string_view where) {
  if (mesh.indices.size() % 3 != 0)
    throw SceneError(fmt::format("{}: {} indices is not a multiple of 3", where, mesh.indices.size()));
  const std::size_t n = mesh.positions.size();
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= n)
      throw SceneError(fmt::format("{}: index {} (at {}) is out of range: the mesh has {} vertices", where,
                                   mesh.indices[i], i, n));
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    throw SceneError(fmt::format("{}: {} normals for {} positions", where, mesh.normals.size(), n));
  if (!mesh.uvs.empty() && mesh.uvs.size() != n)
    throw SceneError(fmt::format("{}: {} uvs for {} positions", where, mesh.uvs.size(), n));
  if (!mesh.tangents.empty() && mesh.tangents.size() != n)
    throw SceneError(fmt::format("{}: {} tangents for {} positions", where, mesh.tangents.size(), n));
  check_finite(mesh.positions, "position", where);
  check_finite(mesh.normals, "normal", where);
  check_finite(mesh.uvs, "uv", where);
  check_finite(mesh.tangents, "tangent", where);
  if (!mesh.tangent_signs.empty() && mesh.tangent_signs.size() != mesh.tangents.size())
    throw SceneError(fmt::format("{}: {} tangent signs for {} tangents", where, mesh.tangent_signs.size(),
                                 mesh.tangents.size()));
  for (float s : mesh.tangent_signs)
    if (s != 1.0f && s != -1.0f) throw SceneError(fmt::format("{}: a tangent sign is {}, not ±1", where, s));

  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    if (has_zero_area(mesh.positions[i0], mesh.positions[i1], mesh.positions[i2])) continue;
    mesh.indices[kept++] = i0;
    mesh.indices[kept++] = i1;
    mesh.indices[kept++] = i2;
  }
  const std::size_t dropped = (mesh.indices.size() - kept) / 3;
  mesh.indices.resize(kept);
  return dropped;
}

}  // namespace prism::loaders
