#include <gtest/gtest.h>

#include "prism/core/error.h"
#include "prism/core/pcg32.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/load_scene.h"
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
}

}  // namespace
}  // namespace prism
