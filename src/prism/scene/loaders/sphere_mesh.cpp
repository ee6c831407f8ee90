#include "prism/scene/loaders/sphere_mesh.h"

#include <cmath>
#include <numbers>

namespace prism::loaders {

TriangleMesh make_uv_sphere(const Vec3f& center, float radius, int rings) {
  rings = std::max(rings, 2);
  const int segments = 2 * rings;
  TriangleMesh mesh;
  // Vertex rows 0..rings; each row has segments+1 vertices so the uv seam has its own copy.
  for (int r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;  // from +y
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      const Vec3f n(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                    static_cast<float>(-std::sin(theta) * std::sin(phi)));
      mesh.positions.push_back(center + n * radius);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(static_cast<float>(s) / segments, static_cast<float>(r) / rings);
    }
  }
  const auto vertex = [segments](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = vertex(r, s), b = vertex(r + 1, s), c = vertex(r + 1, s + 1), d = vertex(r, s + 1);
      // Going down a row and along +phi (towards -z from +x) is counter-clockwise from outside.
      if (r != 0) mesh.indices.insert(mesh.indices.end(), {a, b, d});
      if (r != rings - 1) mesh.indices.insert(mesh.indices.end(), {d, b, c});
    }
  }
  return mesh;
}

}  // namespace prism::loaders
