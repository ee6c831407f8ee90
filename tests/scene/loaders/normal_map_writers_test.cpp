// Normal and bump maps survive Prism's scene writers: written as GLB, JSON and pbrt-v4 and
// loaded back, a material keeps its normal map (the same 8-bit texels, read as linear data,
// not sRGB) and its scale, and its bump map (JSON, pbrt-v4); what a format cannot say is
// refused: pbrt-v4 a normal scale other than 1, glTF any bump map.
#include <gtest/gtest.h>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/scene_summary.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/scene_writers.h"

namespace prism::loaders {
namespace {

// A floor with uvs and normals, a grey environment, and a 2×2 normal map whose texels
// are exact 8-bit values (k / 255), so that a PNG round trip keeps them bit for bit.
Scene normal_mapped_floor(float normal_scale) {
  Scene scene;
  scene.name = "normal-mapped-floor";
  TextureImage map;
  map.name = "bumps";
  map.width = map.height = 2;
  map.channels = 3;
  for (const int v : {128, 128, 255, 200, 128, 220, 128, 60, 230, 90, 170, 240}) map.texels.push_back(v / 255.0f);
  scene.textures.push_back(map);
  Material m;
  m.name = "floor";
  m.type = MaterialType::diffuse;
  m.normal_texture = 0;
  m.normal_scale = normal_scale;
  scene.materials.push_back(m);
  TriangleMesh floor;
  floor.name = "floor";
  floor.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  floor.indices = {0, 2, 1, 0, 3, 2};
  floor.normals.assign(4, Vec3f(0, 1, 0));
  floor.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene.meshes.push_back(floor);
  Light sky;
  sky.type = LightType::environment;
  sky.intensity = 1.0f;
  scene.lights.push_back(sky);
  scene.camera.eye = Vec3f(0, 3, 0.1f);
  return scene;
}

// The same floor with a grey 2×2 bump map instead.
Scene bump_mapped_floor() {
  Scene scene = normal_mapped_floor(1.0f);
  scene.materials[0].normal_texture = -1;
  TextureImage heights;
  heights.name = "heights";
  heights.width = heights.height = 2;
  heights.channels = 1;
  for (const int v : {0, 64, 128, 255}) heights.texels.push_back(v / 255.0f);
  scene.textures[0] = heights;
  scene.materials[0].bump_texture = 0;
  scene.materials[0].bump_scale = 0.125f;
  return scene;
}

TEST(NormalMapWriters, JsonAndPbrtKeepBumpMapsAndGlbRefusesThem) {
  test::ScratchFolder dir;
  const Scene original = bump_mapped_floor();
  for (const char* name : {"bumps.json", "bumps.pbrt"}) {
    const std::filesystem::path path = dir / name;
    if (path.extension() == ".json") write_scene_json(original, path);
    else write_scene_pbrt(original, path);
    const Scene loaded = load_scene(path.string());
    const Material& m = loaded.materials[loaded.meshes[0].material];
    ASSERT_GE(m.bump_texture, 0) << name;
    EXPECT_EQ(m.bump_scale, 0.125f) << name;
    EXPECT_EQ(loaded.textures[static_cast<std::size_t>(m.bump_texture)].linear_values(),
              original.textures[0].linear_values())
        << name;
  }
  EXPECT_NE(test::error_of<UsageError>([&] { write_scene_glb(original, dir / "bumps.glb"); }).find("bump map"),
            std::string::npos);
}

// `prism info` says which materials carry the maps, so a user sees that they were read.
TEST(NormalMapWriters, TheSceneSummaryCountsMappedMaterials) {
  const std::string normal = format_scene_summary(normal_mapped_floor(1.0f));
  EXPECT_NE(normal.find("materials 1 (1 diffuse; 0 emissive, 1 normal-mapped)"), std::string::npos) << normal;
  const std::string bump = format_scene_summary(bump_mapped_floor());
  EXPECT_NE(bump.find("materials 1 (1 diffuse; 0 emissive, 1 bump-mapped)"), std::string::npos) << bump;
}

TEST(NormalMapWriters, EveryFormatKeepsTheMapAndItsScale) {
  test::ScratchFolder dir;
  for (const char* name : {"floor.glb", "floor.json", "floor.pbrt"}) {
    const std::filesystem::path path = dir / name;
    const bool pbrt = path.extension() == ".pbrt";
    const Scene original = normal_mapped_floor(pbrt ? 1.0f : 0.75f);
    if (path.extension() == ".glb") write_scene_glb(original, path);
    else if (path.extension() == ".json") write_scene_json(original, path);
    else write_scene_pbrt(original, path);
    const Scene loaded = load_scene(path.string());
    ASSERT_EQ(loaded.meshes.size(), 1u) << name;
    const Material& m = loaded.materials[loaded.meshes[0].material];
    ASSERT_GE(m.normal_texture, 0) << name;
    EXPECT_EQ(m.normal_scale, original.materials[0].normal_scale) << name;
    const TextureImage& t = loaded.textures[static_cast<std::size_t>(m.normal_texture)];
    EXPECT_EQ(t.linear_values(), original.textures[0].linear_values()) << name;
  }
  EXPECT_NE(test::error_of<UsageError>([&] { write_scene_pbrt(normal_mapped_floor(0.5f), dir / "scaled.pbrt"); })
                .find("normal map"),
            std::string::npos);
}

}  // namespace
}  // namespace prism::loaders
