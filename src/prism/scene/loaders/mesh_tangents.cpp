#include "prism/scene/loaders/mesh_tangents.h"

#include <algorithm>
#include <cmath>

#include "prism/core/frame.h"

namespace prism::loaders {
namespace {

struct Accumulated {
  Vec3f tangent{0.0f};  // angle-weighted sum of unit dP/du in the vertex's tangent plane
  float weight = 0.0f;
};

// Interior angle of the triangle at corner p between the edges to a and b.
float corner_angle(const Vec3f& p, const Vec3f& a, const Vec3f& b) {
  const Vec3f e1 = a - p, e2 = b - p;
  const float l1 = length(e1), l2 = length(e2);
  if (!(l1 > 0.0f && l2 > 0.0f)) return 0.0f;
  return std::acos(std::clamp(dot(e1, e2) / (l1 * l2), -1.0f, 1.0f));
}

// v projected onto the plane perpendicular to unit n, normalised (zero if it vanishes).
Vec3f in_plane(const Vec3f& v, const Vec3f& n) {
  const Vec3f p = v - n * dot(n, v);
  const float len = length(p);
  return len > 0.0f ? p / len : Vec3f(0.0f);
}

}  // namespace

bool generate_tangents(TriangleMesh& mesh) {
  const std::size_t n = mesh.positions.size();
  if (mesh.normals.size() != n || mesh.uvs.size() != n) return false;
  // Unit normals (a zero normal has no tangent plane: its vertex gets x and +1).
  std::vector<Vec3f> normals(n);
  for (std::size_t v = 0; v < n; ++v) {
    const float len = length(mesh.normals[v]);
    normals[v] = len > 0.0f ? mesh.normals[v] / len : Vec3f(0.0f);
  }
  std::vector<Accumulated> sides[2] = {std::vector<Accumulated>(n), std::vector<Accumulated>(n)};  // +1, −1
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t idx[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    const Vec3f& p0 = mesh.positions[idx[0]];
    const Vec3f e1 = mesh.positions[idx[1]] - p0, e2 = mesh.positions[idx[2]] - p0;
    const Vec2f& uv0 = mesh.uvs[idx[0]];
    const float du1 = mesh.uvs[idx[1]].x - uv0.x, dv1 = mesh.uvs[idx[1]].y - uv0.y;
    const float du2 = mesh.uvs[idx[2]].x - uv0.x, dv2 = mesh.uvs[idx[2]].y - uv0.y;
    // e1 = dP/du du1 + dP/dv dv1 and e2 likewise: solve the 2×2 system. A triangle whose
    // uvs are collinear has no uv derivatives and contributes nothing.
    const float det = du1 * dv2 - du2 * dv1;
    if (!(std::abs(det) > 0.0f) || !std::isfinite(1.0f / det)) continue;
    const Vec3f dp_du = (e1 * dv2 - e2 * dv1) / det;
    const Vec3f dp_dv = (e2 * du1 - e1 * du2) / det;
    if (!std::isfinite(length(dp_du)) || !std::isfinite(length(dp_dv))) continue;  // det near underflow
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = idx[c];
      const Vec3f& normal = normals[v];
      const Vec3f t_dir = in_plane(dp_du, normal), up_dir = in_plane(-dp_dv, normal);
      if (t_dir == Vec3f(0.0f)) continue;
      const float angle = corner_angle(mesh.positions[v], mesh.positions[idx[(c + 1) % 3]], mesh.positions[idx[(c + 2) % 3]]);
      // This triangle's handedness at the corner: does n × t point up the image?
      const int side = dot(cross(normal, t_dir), up_dir) >= 0.0f ? 0 : 1;
      Accumulated& a = sides[side][v];
      a.tangent += t_dir * angle;
      a.weight += angle;
    }
  }
  mesh.tangents.assign(n, Vec3f(0.0f));
  mesh.tangent_signs.assign(n, 1.0f);
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3f& normal = normals[v];
    if (normal == Vec3f(0.0f)) {
      mesh.tangents[v] = Vec3f(1.0f, 0.0f, 0.0f);
      continue;
    }
    const int side = sides[1][v].weight > sides[0][v].weight ? 1 : 0;
    // Gram–Schmidt: the accumulated tangent made exactly perpendicular to the normal.
    const Vec3f t = in_plane(sides[side][v].tangent, normal);
    if (t == Vec3f(0.0f)) {
      mesh.tangents[v] = Frame::from_normal(normal).s;
      continue;
    }
    mesh.tangents[v] = t;
    mesh.tangent_signs[v] = side == 0 ? 1.0f : -1.0f;
  }
  return true;
}

}  // namespace prism::loaders
