// Sheen end to end (bsdf/sheen.h): a sheened floor under a white sky renders its albedo
// with every light estimator in both transports; the JSON keys and their rules; glTF's
// KHR_materials_sheen; the writers (JSON and GLB keep it, pbrt-v4 refuses it); the image
// fingerprint and `prism info`.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/bsdf/sheen.h"
#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"
#include "scene/loaders/loader_test_files.h"
#include "support/floor_under_sky.h"
#include "support/one_triangle_gltf.h"
#include "support/write_and_reload.h"

namespace prism {
namespace {

using test::floor_under_white_sky;

// Radiance from the floor = c Ê + (1 − c Ê) ρ with the sky's L = 1 (the sheen reflects
// c Ê(1, r), the Lambertian base the rest). In the 1° view cos θo ≥ cos 0.71°. The bound is
// 5σ of the film's noise plus 5e-4 relative (float accumulation, as the other furnaces),
// plus c × the table's error (0.006, tests/bsdf/sheen_test.cpp): the base's weight uses the
// table, the sheen's own reflection is sampled. Grey colours upsample to flat spectra.
TEST(SheenRender, SheenedFloorUnderAWhiteSkyShowsItsAlbedoOnEveryEstimator) {
  const double rho = 0.5, c = 0.8;
  for (float r : {0.5f, 1.0f}) {
    const Scene scene = floor_under_white_sky(R"({"name": "floor", "type": "diffuse", "base_color": [0.5, 0.5, 0.5],
        "sheen_color": [0.8, 0.8, 0.8], "sheen_roughness": )" + std::to_string(r) + "}");
    const double a_s = c * std::min(1.0f, bsdf::sheen_directional_albedo(1.0f, r));
    const double expected = a_s + (1.0 - a_s) * rho;
    test::expect_floor_radiance(scene, expected, c * 0.006, "r " + std::to_string(r));
  }
}

TEST(SheenRender, JsonKeysAndTheirRules) {
  const auto error = [](const std::string& material) {
    return test::error_of<SceneError>([&] { floor_under_white_sky(material); });
  };
  EXPECT_NE(error(R"({"name": "floor", "type": "dielectric", "sheen_color": [1, 1, 1]})")
                .find("materials[0].sheen_color: a dielectric takes no sheen"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "sheen_roughness": 0.2})")
                .find("materials[0].sheen_roughness: give 'sheen_color'"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "sheen_color": [1.5, 0, 0]})")
                .find("materials[0].sheen_color: sheen colour components must be in [0, 1]"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "sheen_color": [1, 1, 1], "sheen_roughness": 2})")
                .find("materials[0].sheen_roughness"),
            std::string::npos);
  const Scene s = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "sheen_color": [0.9, 0.2, 0.1],
      "sheen_roughness": 0.6, "clearcoat": 1})");
  const Material& m = s.materials[0];
  EXPECT_TRUE(m.has_sheen());
  EXPECT_EQ(m.sheen_color, Vec3f(0.9f, 0.2f, 0.1f));
  EXPECT_FLOAT_EQ(m.sheen_roughness, 0.6f);
  const std::string summary = format_scene_summary(s);
  EXPECT_NE(summary.find("1 clear-coated, 1 with sheen"), std::string::npos) << summary;
  EXPECT_FALSE(floor_under_white_sky(R"({"name": "floor", "type": "diffuse", "sheen_color": [0, 0, 0]})")
                   .materials[0]
                   .has_sheen());
}

Scene sheen_gltf_with_material(const std::string& material) {
  return test::one_triangle_gltf(material, "KHR_materials_sheen");
}

TEST(SheenRender, GltfSheenFactorsAndRules) {
  const Scene s = sheen_gltf_with_material(
      R"({"extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.5, 0.25, 1], "sheenRoughnessFactor": 0.3}}})");
  EXPECT_TRUE(s.materials[0].has_sheen());
  EXPECT_EQ(s.materials[0].sheen_color, Vec3f(0.5f, 0.25f, 1.0f));
  EXPECT_FLOAT_EQ(s.materials[0].sheen_roughness, 0.3f);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("KHR_materials_sheen"), std::string::npos) << w;
  // The default colour is black: no sheen, whatever the roughness.
  EXPECT_FALSE(sheen_gltf_with_material(R"({"extensions": {"KHR_materials_sheen": {"sheenRoughnessFactor": 0.3}}})")
                   .materials[0]
                   .has_sheen());
  const Scene glass = sheen_gltf_with_material(R"({"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1]}}})");
  EXPECT_FALSE(glass.materials[0].has_sheen());
  bool said = false;
  for (const std::string& w : glass.warnings)
    said |= w.find("materials[0].extensions.KHR_materials_sheen: ignored on a transmitting material") !=
            std::string::npos;
  EXPECT_TRUE(said);
  for (const auto& [sheen, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"({"sheenColorFactor": [2, 0, 0]})", "sheenColorFactor components must be in [0, 1]"},
           {R"({"sheenColorFactor": [1, 0]})", "sheenColorFactor must be an array of three numbers"},
           {R"({"sheenColorFactor": [1, 1, 1], "sheenRoughnessFactor": -1})", "sheenRoughnessFactor must be in [0, 1]"}}) {
    const std::string material = R"({"extensions": {"KHR_materials_sheen": )" + sheen + "}}";
    const std::string message = test::error_of<SceneError>([&] { sheen_gltf_with_material(material); });
    EXPECT_NE(message.find("materials[0].extensions.KHR_materials_sheen: " + expected), std::string::npos)
        << sheen << " → " << message;
  }
}

// JSON and GLB keep colour and roughness; pbrt-v4 has no sheen: its writer refuses the
// scene in one line before writing anything.
TEST(SheenRender, WritersKeepTheSheenOrRefuseIt) {
  const Scene original = floor_under_white_sky(R"({"name": "floor", "type": "diffuse", "base_color": [0.2, 0.4, 0.6],
      "sheen_color": [0.7, 0.5, 0.3], "sheen_roughness": 0.45})");
  test::ScratchFolder dir;
  for (const char* name : {"floor.json", "floor.glb"}) {
    const Scene loaded = test::write_and_reload(original, dir / name);
    const Material& m = loaded.materials[loaded.meshes[0].material];
    EXPECT_EQ(m.sheen_color, Vec3f(0.7f, 0.5f, 0.3f)) << name;
    EXPECT_FLOAT_EQ(m.sheen_roughness, 0.45f) << name;
  }
  const std::string message =
      test::error_of<UsageError>([&] { loaders::write_scene_pbrt(original, dir / "floor.pbrt"); });
  EXPECT_NE(message.find("pbrt writer: material 'floor' has a sheen, which pbrt-v4 cannot hold"), std::string::npos)
      << message;
  EXPECT_FALSE(std::filesystem::exists(dir / "floor.pbrt"));
}

// A checkpoint of one sheen does not resume as another (renderer.h's fingerprint).
TEST(SheenRender, TheSheenIsPartOfTheImageFingerprint) {
  RenderSettings s;
  s.width = s.height = 4;
  const std::string sheened = R"({"name": "floor", "type": "diffuse", "sheen_color": [1, 1, 1], "sheen_roughness": 0.2})";
  const std::uint64_t without = image_fingerprint(floor_under_white_sky(R"({"name": "floor", "type": "diffuse"})"), s);
  Scene a = floor_under_white_sky(sheened);
  const std::uint64_t with = image_fingerprint(a, s);
  EXPECT_NE(with, without);
  a.materials[0].sheen_roughness = 0.3f;
  EXPECT_NE(image_fingerprint(a, s), with);
  Scene b = floor_under_white_sky(sheened);
  b.materials[0].sheen_color = Vec3f(1.0f, 0.5f, 1.0f);
  EXPECT_NE(image_fingerprint(b, s), with);
}

}  // namespace
}  // namespace prism
