#include <array>

#include "prism/color/tabulated_data.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/emission.h"
#include "prism/scene/spectral_inputs.h"

namespace prism {
namespace {

// Appends a planar quad (a, b, c, d in order around its boundary) as two triangles.
void add_quad(TriangleMesh& mesh, const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& d) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
  mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// A block standing on the floor: its top face's four corners and its height.
TriangleMesh make_block(std::string name, const std::array<Vec3f, 4>& top, std::uint32_t material) {
  TriangleMesh mesh;
  mesh.name = std::move(name);
  mesh.material = material;
  add_quad(mesh, top[0], top[1], top[2], top[3]);
  for (int i = 0; i < 4; ++i) {
    const Vec3f& a = top[i];
    const Vec3f& b = top[(i + 1) % 4];
    add_quad(mesh, Vec3f(a.x, 0.0f, a.z), a, b, Vec3f(b.x, 0.0f, b.z));
  }
  return mesh;
}

TriangleMesh make_wall(std::string name, const Vec3f& a, const Vec3f& b, const Vec3f& c,
                       const Vec3f& d, std::uint32_t material) {
  TriangleMesh mesh;
  mesh.name = std::move(name);
  mesh.material = material;
  add_quad(mesh, a, b, c, d);
  return mesh;
}

}  // namespace

Scene make_cornell_box() {
  Scene scene;
  scene.name = "cornell-box";
  // Linear Rec.709 reflectances and light radiance of the pbrt-v4 Cornell box, so Prism
  // and pbrt-v4 can render the same scene (see the performance issue).
  enum : std::uint32_t { kWhite, kRed, kGreen, kLight };
  const auto diffuse = [](const char* name, Vec3f reflectance) {
    Material m;
    m.name = name;
    m.base_color = reflectance;
    return m;
  };
  scene.materials = {diffuse("white", {0.725f, 0.71f, 0.68f}), diffuse("red", {0.63f, 0.065f, 0.05f}),
                     diffuse("green", {0.14f, 0.45f, 0.091f}), diffuse("light", Vec3f(0.78f))};
  // Radiance (17, 12, 4) in linear Rec.709: its luminance in nits, with that chromaticity.
  const Vec3f light_rgb(17.0f, 12.0f, 4.0f);
  scene.materials[kLight].emission.color = light_rgb;
  scene.materials[kLight].emission.luminance_nits =
      static_cast<float>(relative_luminance(light_rgb, ColorPickerSpace::srgb));

  scene.meshes.push_back(make_wall("floor", {552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f},
                                   {549.6f, 0, 559.2f}, kWhite));
  scene.meshes.push_back(make_wall("ceiling", {556, 548.8f, 0}, {556, 548.8f, 559.2f},
                                   {0, 548.8f, 559.2f}, {0, 548.8f, 0}, kWhite));
  scene.meshes.push_back(make_wall("back", {549.6f, 0, 559.2f}, {0, 0, 559.2f},
                                   {0, 548.8f, 559.2f}, {556, 548.8f, 559.2f}, kWhite));
  scene.meshes.push_back(make_wall("green-wall", {0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0},
                                   {0, 548.8f, 559.2f}, kGreen));
  scene.meshes.push_back(make_wall("red-wall", {552.8f, 0, 0}, {549.6f, 0, 559.2f},
                                   {556, 548.8f, 559.2f}, {556, 548.8f, 0}, kRed));
  scene.meshes.push_back(make_block("short-block",
                                    {Vec3f(130, 165, 65), Vec3f(82, 165, 225),
                                     Vec3f(240, 165, 272), Vec3f(290, 165, 114)},
                                    kWhite));
  scene.meshes.push_back(make_block("tall-block",
                                    {Vec3f(423, 330, 247), Vec3f(265, 330, 296),
                                     Vec3f(314, 330, 456), Vec3f(472, 330, 406)},
                                    kWhite));
  // The light hangs 0.5 mm below the ceiling (as in the Mitsuba scene) so it does not
  // coincide with it. Winding chosen so the front face (emitting side) points down.
  constexpr float kLightY = 548.8f - 0.5f;
  scene.meshes.push_back(make_wall("light", {343, kLightY, 227}, {343, kLightY, 332},
                                   {213, kLightY, 332}, {213, kLightY, 227}, kLight));

  scene.camera.eye = Vec3f(278, 273, -800);
  scene.camera.target = Vec3f(278, 273, -799);
  scene.camera.up = Vec3f(0, 1, 0);
  scene.camera.fov_degrees = 39.3077f;
  scene.camera.name = "default";
  scene.default_width = 512;
  scene.default_height = 512;
  return scene;
}

Scene make_cornell_box_measured() {
  Scene scene = make_cornell_box();
  scene.name = "cornell-box-measured";
  // Cornell's measured reflectances (data/cornell_box/, 400–700 nm every 4 nm) for the
  // white, green and red walls, and the light's measured relative spectral radiance, at the
  // luminance of the RGB box's light so that both render at the same exposure.
  const color::data::Table walls = color::data::cornell_box_reflectance();
  const auto column = [](const color::data::Table& t, int c) {
    std::vector<double> nm, values;
    for (int i = 0; i < t.rows; ++i) {
      nm.push_back(t.at(i, 0));
      values.push_back(t.at(i, c));
    }
    return color::PiecewiseLinearSpectrum(std::move(nm), std::move(values));
  };
  for (Material& m : scene.materials) {
    const int c = m.name == "white" ? 1 : m.name == "green" ? 2 : m.name == "red" ? 3 : 0;
    if (c == 0) continue;
    set_base_color_spectrum(m, column(walls, c));
  }
  for (Material& m : scene.materials)
    if (m.is_emissive()) set_emission_spectrum(m.emission, column(color::data::cornell_box_light(), 1));
  return scene;
}

}  // namespace prism
