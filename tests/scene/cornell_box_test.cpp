#include <gtest/gtest.h>

#include "prism/core/error.h"
#include "prism/core/pcg32.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/scene_summary.h"
#include "support/chi_square.h"

namespace prism {
namespace {

const TriangleMesh& mesh_named(const Scene& scene, const std::string& name) {
  for (const auto& m : scene.meshes)
    if (m.name == name) return m;
  throw std::runtime_error("no mesh " + name);
}

TEST(CornellBox, HasTheClassicContents) {
  const Scene scene = make_cornell_box();
  EXPECT_NO_THROW(validate_scene(scene));
  // Five walls and the light are quads (2 triangles); each block has a top and four sides.
  EXPECT_EQ(scene.triangle_count(), 5u * 2 + 2u * 10 + 2);
  EXPECT_EQ(scene.default_width, 512);
  EXPECT_EQ(scene.default_height, 512);
  EXPECT_GT(scene.materials[scene.meshes[3].material].base_color.y, 0.3f);  // green wall
}

TEST(CornellBox, LightFacesDownIntoTheRoom) {
  const Scene scene = make_cornell_box();
  const TriangleMesh& light = mesh_named(scene, "light");
  EXPECT_TRUE(scene.materials[light.material].is_emissive());
  for (std::size_t t = 0; t < light.triangle_count(); ++t) {
    const Vec3f& p0 = light.positions[light.indices[3 * t]];
    const Vec3f& p1 = light.positions[light.indices[3 * t + 1]];
    const Vec3f& p2 = light.positions[light.indices[3 * t + 2]];
    EXPECT_LT(cross(p1 - p0, p2 - p0).y, 0.0f);
  }
}

TEST(CornellBox, RedWallOnTheLeftOfTheView) {
  // The camera looks along +z with +y up, so the image's left is world +x (x = 556).
  const Scene scene = make_cornell_box();
  EXPECT_GT(mesh_named(scene, "red-wall").positions[0].x, 500.0f);
  EXPECT_LT(mesh_named(scene, "green-wall").positions[0].x, 1.0f);
}

// Cornell's measurements (data/cornell_box/): spot values of the table as published with
// the Mitsuba 3 scene, on the classic box's geometry and light luminance.
TEST(CornellBox, MeasuredVariantCarriesCornellsSpectra) {
  const Scene rgb = make_cornell_box(), measured = load_scene("cornell-box-measured");
  EXPECT_NO_THROW(validate_scene(measured));
  EXPECT_EQ(measured.name, "cornell-box-measured");
  ASSERT_EQ(measured.meshes.size(), rgb.meshes.size());
  for (std::size_t i = 0; i < rgb.meshes.size(); ++i) EXPECT_EQ(measured.meshes[i].positions, rgb.meshes[i].positions);
  const auto material = [&](const char* name) -> const Material& {
    for (const Material& m : measured.materials)
      if (m.name == name) return m;
    throw std::runtime_error(std::string("no material ") + name);
  };
  ASSERT_TRUE(material("white").base_color_spectrum && material("green").base_color_spectrum &&
              material("red").base_color_spectrum);
  EXPECT_DOUBLE_EQ((*material("white").base_color_spectrum)(400.0), 0.343);
  EXPECT_DOUBLE_EQ((*material("green").base_color_spectrum)(404.0), 0.096);
  EXPECT_DOUBLE_EQ((*material("red").base_color_spectrum)(408.0), 0.048);
  const Material& light = material("light");
  ASSERT_TRUE(light.emission.spectrum);
  EXPECT_DOUBLE_EQ((*light.emission.spectrum)(550.0), 11.8);  // between 8 (500 nm) and 15.6 (600 nm)
  EXPECT_EQ(light.emission.luminance_nits, rgb.materials[3].emission.luminance_nits);
  EXPECT_NE(format_scene_summary(measured).find("materials 4 (4 diffuse; 1 emissive, 4 with spectra)"),
            std::string::npos)
      << format_scene_summary(measured);
  // Their colours under D65 are the box's: a red wall reflecting mostly long wavelengths.
  const Vec3f red = material("red").base_color, green = material("green").base_color;
  EXPECT_GT(red.x, 4.0f * red.y);
  EXPECT_GT(green.y, 2.0f * green.x);
}

TEST(LoadScene, ResolvesBuiltinsAndReportsErrors) {
  EXPECT_EQ(load_scene("cornell-box").name, "cornell-box");
  EXPECT_THROW(load_scene("no-such-scene"), UsageError);
  EXPECT_THROW(load_scene("/nonexistent/dir/scene.json"), IoError);
}

TEST(Scene, ValidationCatchesBadData) {
  Scene scene = make_cornell_box();
  scene.meshes[0].indices[2] = 999;
  EXPECT_THROW(validate_scene(scene), SceneError);
  scene = make_cornell_box();
  scene.meshes[0].positions[0].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(validate_scene(scene), SceneError);
  scene = make_cornell_box();
  scene.meshes[0].material = 42;
  EXPECT_THROW(validate_scene(scene), SceneError);
  EXPECT_THROW(validate_scene(Scene{}), SceneError);
  // Spectra built in code rather than by a loader: empty, out of range, or on an environment.
  scene = make_cornell_box_measured();
  EXPECT_NO_THROW(validate_scene(scene));
  scene.materials[0].base_color_spectrum = color::PiecewiseLinearSpectrum();
  EXPECT_THROW(validate_scene(scene), SceneError);
  scene = make_cornell_box();
  scene.materials[0].base_color_spectrum = color::PiecewiseLinearSpectrum({400.0, 700.0}, {0.5, 1.5});
  EXPECT_THROW(validate_scene(scene), SceneError);
  scene = make_cornell_box();
  scene.materials[3].emission.spectrum = color::PiecewiseLinearSpectrum({400.0, 700.0}, {1.0, -1.0});
  EXPECT_THROW(validate_scene(scene), SceneError);
  scene = make_cornell_box();
  Light sky;
  sky.type = LightType::environment;
  sky.spectrum = color::PiecewiseLinearSpectrum({400.0, 700.0}, {1.0, 1.0});
  scene.lights.push_back(sky);
  EXPECT_NO_THROW(validate_scene(scene));  // a constant sky may have a spectrum
  scene.textures.push_back(TextureImage{});
  scene.lights.back().environment_texture = 0;
  EXPECT_THROW(validate_scene(scene), SceneError);  // a map's texels are its colours
}

}  // namespace
}  // namespace prism
