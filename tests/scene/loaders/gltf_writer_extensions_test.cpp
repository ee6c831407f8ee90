// The GLB writer's extensionsUsed: exactly the extensions the file uses (glTF 2.0 §3.12),
// absent when there are none, instead of every extension the writer knows.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "prism/scene/loaders/gltf_writer.h"
#include "support/scratch_folder.h"

namespace prism::loaders {
namespace {

// The JSON chunk of a GLB file: 12-byte header, then the chunk's length and type.
nlohmann::json glb_json(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::uint32_t length = 0;
  EXPECT_GE(bytes.size(), 20u);
  std::memcpy(&length, bytes.data() + 12, 4);
  return nlohmann::json::parse(std::string(bytes.data() + 20, length));
}

Scene one_triangle(const Material& m) {
  Scene scene;
  scene.name = "t";
  scene.materials = {m};
  TriangleMesh mesh;
  mesh.name = "t";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2};
  scene.meshes = {mesh};
  return scene;
}

TEST(GlbWriter, ExtensionsUsedNamesOnlyWhatTheFileUses) {
  test::ScratchFolder dir;
  Material plain;
  plain.type = MaterialType::metallic_roughness;
  write_scene_glb(one_triangle(plain), dir / "plain.glb");
  EXPECT_FALSE(glb_json(dir / "plain.glb").contains("extensionsUsed"));

  Material sheen = plain;
  sheen.sheen_color = Vec3f(0.5f);
  sheen.anisotropy = 0.5f;
  write_scene_glb(one_triangle(sheen), dir / "sheen.glb");
  const nlohmann::json doc = glb_json(dir / "sheen.glb");
  ASSERT_TRUE(doc.contains("extensionsUsed"));
  EXPECT_EQ(doc["extensionsUsed"], nlohmann::json({"KHR_materials_anisotropy", "KHR_materials_sheen"}));
}

}  // namespace
}  // namespace prism::loaders
