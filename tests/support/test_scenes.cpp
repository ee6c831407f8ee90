#include "support/test_scenes.h"

#include "prism/render/renderer.h"
#include "support/film_statistics.h"

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

RenderSettings floor_from_above_render_settings(TransportKind kind) {
  RenderSettings s;
  s.width = s.height = 16;
  s.samples_per_pixel = 64;
  s.path.max_depth = 1;
  s.transport.kind = kind;
  return s;
}

Scene make_floor_under_overhead_sun(const Material& material, float illuminance_lux) {
  Scene scene = make_grey_floor_seen_from_above(5.0f, 30.0f);
  scene.meshes[0].uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene.materials = {material};
  Light sun;
  sun.type = LightType::directional;
  sun.direction = Vec3f(0, -1, 0);
  sun.intensity = illuminance_lux;
  scene.lights.push_back(sun);
  return scene;
}

Scene make_sunlit_uv_floor(const Vec3f& toward_light, bool mirrored_u) {
  Scene scene = make_grey_floor_seen_from_above(90.0f, 10.0f);
  scene.materials[0].type = MaterialType::diffuse;
  TriangleMesh& floor = scene.meshes[0];
  floor.normals.assign(4, Vec3f(0, 1, 0));
  floor.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (mirrored_u)
    for (Vec2f& uv : floor.uvs) uv.x = 1.0f - uv.x;
  Light sun;
  sun.type = LightType::directional;
  sun.direction = -toward_light / length(toward_light);
  sun.intensity = 1.0f;
  scene.lights.push_back(sun);
  return scene;
}

TriangleMesh make_uv_triangle() {
  TriangleMesh mesh;
  mesh.name = "triangle";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
  mesh.indices = {0, 1, 2};
  return mesh;
}

Scene make_bulb_lit_uv_floor(const Material& material) {
  Scene scene = make_grey_floor_seen_from_above(5.0f, 60.0f);
  scene.meshes[0].uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene.materials = {material};
  Light bulb;
  bulb.type = LightType::point;
  bulb.position = Vec3f(0, 2, 0);
  bulb.intensity = 100.0f;
  scene.lights.push_back(bulb);
  return scene;
}

RenderSettings direct_light_rgb_settings(int size) {
  RenderSettings s;
  s.width = s.height = size;
  s.samples_per_pixel = 4;
  s.path.max_depth = 1;
  s.transport.kind = TransportKind::rgb;
  return s;
}

double direct_light_mean_red(const Scene& scene) {
  RenderSettings settings;
  settings.width = settings.height = 8;
  settings.samples_per_pixel = 2;
  settings.path.max_depth = 1;
  settings.transport.kind = TransportKind::rgb;
  settings.threads = 1;
  return block_estimate(render(scene, settings, RenderHooks{}).film, 0, 0, 8, 8).mean.x;
}

}  // namespace prism::test
