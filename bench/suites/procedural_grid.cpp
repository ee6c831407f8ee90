#include "procedural_grid.h"

#include <algorithm>
#include <cmath>

namespace prism::bench {

Scene make_triangle_grid_scene(std::size_t triangles) {
  Scene scene;
  scene.name = "generated-grid";
  const auto n = static_cast<std::uint32_t>(std::max(1.0, std::floor(std::sqrt(triangles / 2.0))));
  constexpr float kSize = 10.0f;  // metres

  Material floor;
  floor.name = "floor";
  floor.base_color = Vec3f(0.6f, 0.55f, 0.5f);
  Material light;
  light.name = "light";
  light.emission.color = Vec3f(1.0f);
  light.emission.luminance_nits = 1000.0f;
  scene.materials = {floor, light};

  TriangleMesh grid;
  grid.name = "floor";
  grid.material = 0;
  grid.positions.reserve(static_cast<std::size_t>(n + 1) * (n + 1));
  grid.indices.reserve(static_cast<std::size_t>(n) * n * 6);
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) {
      const float x = kSize * (static_cast<float>(i) / n - 0.5f), z = kSize * (static_cast<float>(j) / n - 0.5f);
      grid.positions.emplace_back(x, 0.2f * std::sin(3.0f * x) * std::cos(2.0f * z), z);
    }
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      // Counter-clockwise seen from above (+y): front faces up.
      grid.indices.insert(grid.indices.end(), {a, c, b, b, c, d});
    }
  scene.meshes.push_back(std::move(grid));

  TriangleMesh quad;
  quad.name = "ceiling light";
  quad.material = 1;
  const float h = 4.0f, s = 1.5f;
  quad.positions = {{-s, h, -s}, {s, h, -s}, {s, h, s}, {-s, h, s}};
  quad.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from below: emits downwards
  scene.meshes.push_back(std::move(quad));

  scene.camera.eye = Vec3f(0.0f, 3.0f, -7.0f);
  scene.camera.target = Vec3f(0.0f, 0.0f, 0.0f);
  scene.camera.fov_degrees = 50.0f;
  return scene;
}

}  // namespace prism::bench
