#include "support/test_scenes.h"

namespace prism::test {

Scene make_emitting_enclosure(float albedo, float emitted) {
  Scene scene;
  scene.name = "emitting-enclosure";
  Material wall;
  wall.name = "wall";
  wall.base_color = Vec3f(albedo);
  // Rec.709 white has luminance 1, so radiance is `emitted` in every channel.
  wall.emission.color = Vec3f(1.0f);
  wall.emission.luminance_nits = emitted;
  scene.materials = {wall};
  TriangleMesh mesh;
  mesh.name = "cube";
  // Corners of [-1, 1]^3; each face listed so its counter-clockwise normal points inwards.
  const Vec3f c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7}, {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
  for (const auto& f : faces) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (int k = 0; k < 4; ++k) mesh.positions.push_back(c[f[k]]);
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  scene.meshes.push_back(mesh);
  scene.camera.eye = Vec3f(0, 0, 0);
  scene.camera.target = Vec3f(0.3f, 0.2f, 1);
  scene.camera.fov_degrees = 90.0f;
  return scene;
}

Scene make_grey_floor_seen_from_above(float eye_height, float fov_degrees) {
  Scene scene;
  scene.name = "grey-floor";
  Material grey;
  grey.base_color = Vec3f(0.5f);
  scene.materials = {grey};
  TriangleMesh floor;
  floor.positions = {{-100, 0, -100}, {100, 0, -100}, {100, 0, 100}, {-100, 0, 100}};
  floor.indices = {0, 2, 1, 0, 3, 2};  // front face up
  scene.meshes.push_back(floor);
  scene.camera.eye = Vec3f(0, eye_height, 0);
  scene.camera.target = Vec3f(0, 0, 0);
  scene.camera.up = Vec3f(0, 0, 1);
  scene.camera.fov_degrees = fov_degrees;
  return scene;
}

}  // namespace prism::test
