// The coat's own normal map through the writers: JSON and GLB keep it (texture and scale),
// pbrt-v4, whose coats have no normal map of their own, refuses the scene.
#include <gtest/gtest.h>

#include <string>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "support/scratch_folder.h"
#include "support/test_scenes.h"
#include "support/write_and_reload.h"

namespace prism::loaders {
namespace {

Scene coated_with_normal_map() {
  Scene scene;
  scene.name = "coated";
  TextureImage normal;
  normal.name = "bumps";
  normal.width = normal.height = 2;
  normal.channels = 3;
  normal.texels = {0.6f, 0.5f, 0.9f, 0.4f, 0.5f, 0.9f, 0.5f, 0.6f, 0.9f, 0.5f, 0.4f, 0.9f};
  scene.textures = {normal};
  Material m;
  m.name = "paint";
  m.type = MaterialType::metallic_roughness;
  m.clearcoat = 1.0f;
  m.clearcoat_roughness = 0.1f;
  m.clearcoat_normal_texture = 0;
  m.clearcoat_normal_scale = 0.75f;
  scene.materials = {m};
  scene.meshes = {test::make_uv_triangle()};
  return scene;
}

TEST(ClearcoatNormalFormats, JsonAndGlbKeepTheCoatsNormalMap) {
  test::ScratchFolder dir;
  for (const char* file : {"scene.json", "scene.glb"}) {
    const Scene back = test::write_and_reload(coated_with_normal_map(), dir / file);
    const Material& m = back.materials[back.meshes[0].material];
    ASSERT_GE(m.clearcoat_normal_texture, 0) << file;
    EXPECT_FLOAT_EQ(m.clearcoat_normal_scale, 0.75f) << file;
    const TextureImage& t = back.textures[static_cast<std::size_t>(m.clearcoat_normal_texture)];
    EXPECT_EQ(t.width, 2) << file;
    EXPECT_EQ(t.encoding, TextureEncoding::linear) << file;
    EXPECT_EQ(m.normal_texture, -1) << file;  // the base keeps its own (none)
  }
}

TEST(ClearcoatNormalFormats, PbrtWriterRefusesACoatNormalMap) {
  test::ScratchFolder dir;
  const std::string message = test::error_of<UsageError>(
      [&] { write_scene_pbrt(coated_with_normal_map(), dir / "scene.pbrt"); });
  EXPECT_NE(message.find("'paint' has a coat with its own normal map"), std::string::npos) << message;
}

}  // namespace
}  // namespace prism::loaders
