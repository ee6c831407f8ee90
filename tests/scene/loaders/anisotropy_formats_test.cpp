// Anisotropic roughness in every format (render/anisotropy.h): glTF's
// KHR_materials_anisotropy, the JSON keys, pbrt-v4's uroughness/vroughness, and the three
// writers' round trips; what a format cannot say is refused, not dropped.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "prism/bsdf/microfacet.h"
#include "prism/core/error.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "loader_test_files.h"
#include "support/one_triangle_gltf.h"
#include "support/scratch_folder.h"
#include "support/test_scenes.h"
#include "support/write_and_reload.h"

namespace prism::loaders {
namespace {


TEST(AnisotropyFormats, GltfExtensionGivesStrengthRotationAndTexture) {
  const Scene scene = test::one_triangle_gltf(
      R"({"pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.4},
          "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.6, "anisotropyRotation": 1.25}}})",
      "KHR_materials_anisotropy");
  const Material& m = scene.materials[0];
  EXPECT_FLOAT_EQ(m.anisotropy, 0.6f);
  EXPECT_FLOAT_EQ(m.anisotropy_rotation_rad, 1.25f);
  EXPECT_EQ(m.anisotropy_texture, -1);
  EXPECT_TRUE(m.has_anisotropy());
  for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("ignored"), std::string::npos) << w;
  // Rotations are kept within ±π; out-of-range strengths are an error naming the field.
  const Scene turned = test::one_triangle_gltf(
      R"({"extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.5, "anisotropyRotation": 7.0}}})",
      "KHR_materials_anisotropy");
  EXPECT_NEAR(turned.materials[0].anisotropy_rotation_rad, 7.0f - 2.0f * std::numbers::pi_v<float>, 1e-6f);
  const std::string message = test::error_of<SceneError>([] {
    test::one_triangle_gltf(R"({"extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 1.5}}})",
                            "KHR_materials_anisotropy");
  });
  EXPECT_NE(message.find("KHR_materials_anisotropy: anisotropyStrength must be in [0, 1]"), std::string::npos)
      << message;
}

// pbrt-v4's uroughness and vroughness are α along dP/du and across it (with
// remaproughness false): the narrower sets Prism's roughness, the wider the strength, and
// which of them is wider the rotation.
TEST(AnisotropyFormats, PbrtUroughnessAndVroughnessBecomeStrengthAndRotation) {
  const auto material = [](const std::string& params) {
    const std::string text = "WorldBegin\nMaterial \"conductor\" " + params +
                             " \"bool remaproughness\" false\n"
                             "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n";
    return parse_pbrt_scene(text, "test.pbrt", {});
  };
  const Scene along_u = material("\"float uroughness\" 0.4 \"float vroughness\" 0.1");
  const Material& u = along_u.materials[along_u.meshes[0].material];
  EXPECT_NEAR(u.roughness * u.roughness, 0.1f, 1e-6f);
  EXPECT_NEAR(bsdf::anisotropic_alpha_along(0.1f, u.anisotropy), 0.4f, 1e-6f);
  EXPECT_EQ(u.anisotropy_rotation_rad, 0.0f);
  for (const std::string& w : along_u.warnings) EXPECT_EQ(w.find("anisotropic"), std::string::npos) << w;
  const Scene along_v = material("\"float uroughness\" 0.1 \"float vroughness\" 0.4");
  const Material& v = along_v.materials[along_v.meshes[0].material];
  EXPECT_NEAR(v.roughness * v.roughness, 0.1f, 1e-6f);
  EXPECT_NEAR(v.anisotropy_rotation_rad, std::numbers::pi_v<float> / 2, 1e-6f);
  // A coat stays isotropic: its roughness is the mean, and the file is told so.
  const std::string coated_text =
      "WorldBegin\nMaterial \"coateddiffuse\" \"float uroughness\" 0.1 \"float vroughness\" 0.3\n"
      "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n";
  const Scene coated = parse_pbrt_scene(coated_text, "test.pbrt", {});
  bool said = false;
  for (const std::string& w : coated.warnings) said |= w.find("anisotropic roughness as its mean") != std::string::npos;
  EXPECT_TRUE(said);
}

Scene anisotropic_scene(MaterialType type, float rotation_rad) {
  Scene scene;
  scene.name = "anisotropic";
  Material m;
  m.name = "brushed";
  m.type = type;
  m.base_color = type == MaterialType::dielectric ? Vec3f(1.0f) : Vec3f(0.9f, 0.8f, 0.7f);
  m.roughness = 0.3f;
  m.metallic = 1.0f;
  m.anisotropy = 0.7f;
  m.anisotropy_rotation_rad = rotation_rad;
  scene.materials = {m};
  scene.meshes = {test::make_uv_triangle()};
  return scene;
}

TEST(AnisotropyFormats, JsonAndGlbWritersKeepStrengthAndRotation) {
  test::ScratchFolder dir;
  for (const char* file : {"scene.json", "scene.glb"}) {
    const Scene back =
        test::write_and_reload(anisotropic_scene(MaterialType::metallic_roughness, 0.5f), dir / file);
    const Material& m = back.materials[back.meshes[0].material];
    EXPECT_FLOAT_EQ(m.anisotropy, 0.7f) << file;
    EXPECT_NEAR(m.anisotropy_rotation_rad, 0.5f, 1e-6f) << file;  // JSON holds degrees
  }
}

TEST(AnisotropyFormats, PbrtWriterSaysUvAlignedAnisotropyAndRefusesOtherAngles) {
  test::ScratchFolder dir;
  for (const float rotation : {0.0f, std::numbers::pi_v<float> / 2, -std::numbers::pi_v<float> / 2, std::numbers::pi_v<float>}) {
    for (const MaterialType type : {MaterialType::conductor, MaterialType::dielectric}) {
      const Scene back = test::write_and_reload(anisotropic_scene(type, rotation), dir / "scene.pbrt");
      const Material& m = back.materials[back.meshes[0].material];
      EXPECT_NEAR(m.roughness, 0.3f, 1e-5f) << rotation;
      EXPECT_NEAR(m.anisotropy, 0.7f, 1e-5f) << rotation;
      // Along u (0, π) or along v (±π/2): the direction is the same line either way.
      const bool along_v = std::abs(std::abs(rotation) - std::numbers::pi_v<float> / 2) < 1e-3f;
      EXPECT_NEAR(m.anisotropy_rotation_rad, along_v ? std::numbers::pi_v<float> / 2 : 0.0f, 1e-6f) << rotation;
    }
  }
  const std::string message = test::error_of<UsageError>([&] {
    loaders::write_scene_pbrt(anisotropic_scene(MaterialType::conductor, 0.5f), dir / "angled.pbrt");
  });
  EXPECT_NE(message.find("'brushed'"), std::string::npos) << message;
  EXPECT_NE(message.find("at an angle to the uv axes"), std::string::npos) << message;
}

TEST(AnisotropyFormats, JsonStrengthOutsideZeroToOneIsAnError) {
  const std::string text = R"({"format": "prism-scene/1", "name": "q",
    "materials": [{"name": "m", "type": "conductor", "anisotropy": 1.5}],
    "meshes": [{"name": "q", "material": "m", "positions": [[0,0,0], [1,0,0], [0,1,0]], "indices": [0,1,2]}]})";
  const std::string message = test::error_of<SceneError>([&] { parse_json_scene(text, "test.json", {}, "test", {}); });
  EXPECT_NE(message.find("anisotropy"), std::string::npos) << message;
}

}  // namespace
}  // namespace prism::loaders
