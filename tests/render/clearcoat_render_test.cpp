// Clear-coated materials end to end: a coated floor under a uniform sky renders its known
// albedo on every light estimator and in both transports (the smooth coat is a delta lobe
// beside a non-delta base, which NEE, BSDF sampling and MIS must split correctly), the JSON
// keys and their rules, every reader that brings a coat in (glTF, pbrt-v4, MTL) through the
// scene writers and back, `prism info`, and the image fingerprint.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/bsdf/clearcoat.h"
#include "prism/bsdf/fresnel.h"
#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"
#include "scene/loaders/loader_test_files.h"
#include "support/floor_under_sky.h"
#include "support/write_and_reload.h"

namespace prism {
namespace {

using test::floor_under_white_sky;

// Radiance from the floor = L ∫ f cos dωi = A_c + (1 − A_c) ρ with L = 1: the coat reflects
// A_c = c E(1, r) of the sky and passes the rest to the Lambertian base (bsdf/clearcoat.h).
// In the 1° view cos θo ≥ cos 0.71° (E moves by < 1e-6 there). The bound is 5σ of the
// film's noise plus 5e-4 relative (float accumulation, as the other furnaces), plus for a
// rough coat the table's error in E (≤ 0.002, tests/bsdf/clearcoat_test.cpp) times 1 − ρ:
// the base's weight uses the table, the coat's own reflection is sampled.
TEST(ClearcoatRender, CoatedFloorUnderAWhiteSkyShowsItsAlbedoOnEveryEstimator) {
  const double rho = 0.5, c = 0.8;
  for (float r : {0.0f, 0.4f}) {
    const Scene scene = floor_under_white_sky(R"({"name": "floor", "type": "diffuse", "base_color": [0.5, 0.5, 0.5],
        "clearcoat": 0.8, "clearcoat_roughness": )" + std::to_string(r) + "}");
    const double a_c = c * (r == 0.0f ? bsdf::fresnel_dielectric(1.0f, 1.5f) : bsdf::coat_directional_albedo(1.0f, r));
    const double expected = a_c + (1.0 - a_c) * rho;
    const double table_slack = r == 0.0f ? 0.0 : 0.002 * c * (1.0 - rho);
    test::expect_floor_radiance(scene, expected, table_slack, "r " + std::to_string(r));
  }
}

TEST(ClearcoatRender, JsonKeysAndTheirRules) {
  const auto error = [](const std::string& material) {
    return test::error_of<SceneError>([&] { floor_under_white_sky(material); });
  };
  EXPECT_NE(error(R"({"name": "floor", "type": "dielectric", "clearcoat": 1})")
                .find("materials[0].clearcoat: a dielectric takes no clear coat"),
            std::string::npos);
  // glTF's transmission turns metallic_roughness into glass first: no coat on it either.
  EXPECT_NE(error(R"({"name": "floor", "type": "metallic_roughness", "transmission": 1, "clearcoat": 1})")
                .find("a dielectric takes no clear coat"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "clearcoat_roughness": 0.2})")
                .find("materials[0].clearcoat_roughness: give 'clearcoat'"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "clearcoat": 1.5})").find("materials[0].clearcoat"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "clearcoat": 1, "clearcoat_roughness": -1})")
                .find("materials[0].clearcoat_roughness"),
            std::string::npos);
  const Scene s = floor_under_white_sky(R"({"name": "floor", "type": "conductor", "conductor": "Au", "roughness": 0.3,
      "clearcoat": 0.7, "clearcoat_roughness": 0.1})");
  const Material& m = s.materials[0];
  EXPECT_TRUE(m.has_clearcoat());
  EXPECT_FLOAT_EQ(m.clearcoat, 0.7f);
  EXPECT_FLOAT_EQ(m.clearcoat_roughness, 0.1f);
  const std::string summary = format_scene_summary(s);
  EXPECT_NE(summary.find("1 clear-coated"), std::string::npos) << summary;
}

// JSON and GLB keep weight and roughness; pbrt-v4's coated materials have no weight, so a
// coat comes back whole there, on the same base type with the same roughness.
TEST(ClearcoatRender, EveryWriterKeepsTheCoat) {
  const Scene original = floor_under_white_sky(R"({"name": "floor", "type": "diffuse", "base_color": [0.2, 0.4, 0.6],
      "clearcoat": 0.6, "clearcoat_roughness": 0.25})");
  const Scene metal = floor_under_white_sky(R"({"name": "floor", "type": "conductor", "conductor": "Cu", "roughness": 0.4,
      "clearcoat": 1, "clearcoat_roughness": 0.5})");
  test::ScratchFolder dir;
  for (const Scene* scene : {&original, &metal})
    for (const char* name : {"floor.json", "floor.glb", "floor.pbrt"}) {
      const std::filesystem::path path = dir / name;
      const Scene loaded = test::write_and_reload(*scene, path);
      const Material& m = loaded.materials[loaded.meshes[0].material];
      const Material& m0 = scene->materials[0];
      ASSERT_TRUE(m.has_clearcoat()) << name;
      EXPECT_NEAR(m.clearcoat_roughness, m0.clearcoat_roughness, 1e-6f) << name;
      EXPECT_EQ(m.clearcoat, path.extension() == ".pbrt" ? 1.0f : m0.clearcoat) << name;
      // GLB writes metals as metallic_roughness (glTF has no other), pbrt-v4 and JSON keep the type.
      if (path.extension() != ".glb") {
        EXPECT_EQ(m.type, m0.type) << name;
      }
      if (m0.type == MaterialType::conductor && path.extension() != ".glb") {
        EXPECT_NEAR(m.roughness, m0.roughness, 1e-6f) << name;
        EXPECT_EQ(m.conductor_name, "Cu") << name;
      }
    }
}

// pbrt-v4's coateddiffuse and coatedconductor: the interface's roughness is the coat's (with
// pbrt's remapping), coatedconductor's "conductor." parameters are the base's, and what the
// layering drops is said.
TEST(ClearcoatRender, PbrtCoatedMaterialsBecomeClearCoats) {
  test::ScratchFolder dir;
  const std::string header = R"(LookAt 0 1 0  0 0 0  0 0 1
Camera "perspective" "float fov" [ 30 ]
WorldBegin
)";
  const std::string quad = R"(Shape "trianglemesh" "point3 P" [ -1 0 -1  1 0 -1  1 0 1  -1 0 1 ] "integer indices" [ 0 2 1  0 3 2 ]
)";
  dir.write("coated.pbrt", header + R"(Material "coateddiffuse" "rgb reflectance" [ 0.2 0.3 0.4 ] "float roughness" [ 0.01 ]
)" + quad + R"(Material "coatedconductor" "float interface.roughness" [ 0.04 ] "bool remaproughness" false
  "spectrum conductor.eta" "metal-Au-eta" "spectrum conductor.k" "metal-Au-k" "float conductor.roughness" [ 0.09 ]
)" + quad + R"(Material "coateddiffuse" "float eta" [ 1.33 ] "rgb albedo" [ 0.5 0.5 0.5 ]
)" + quad);
  const Scene s = load_scene((dir / "coated.pbrt").string());
  ASSERT_EQ(s.materials.size(), 3u);
  const Material& diffuse = s.materials[0];
  EXPECT_EQ(diffuse.type, MaterialType::diffuse);
  EXPECT_EQ(diffuse.base_color, Vec3f(0.2f, 0.3f, 0.4f));
  EXPECT_FLOAT_EQ(diffuse.clearcoat, 1.0f);
  // remaproughness (default true): α = sqrt(0.01) = 0.1, r = sqrt(α).
  EXPECT_NEAR(diffuse.clearcoat_roughness, std::sqrt(0.1f), 1e-6f);
  const Material& gold = s.materials[1];
  EXPECT_EQ(gold.type, MaterialType::conductor);
  EXPECT_EQ(gold.conductor_name, "Au");
  EXPECT_NEAR(gold.roughness, 0.3f, 1e-6f);             // α = 0.09 without remapping
  EXPECT_NEAR(gold.clearcoat_roughness, 0.2f, 1e-6f);   // α = 0.04
  EXPECT_TRUE(s.materials[2].has_clearcoat());
  // The approximations come in one warning line, each named there.
  std::string said;
  for (const std::string& w : s.warnings) said += w + "\n";
  int layering = 0;
  for (auto at = said.find("as a clear coat over a"); at != std::string::npos;
       at = said.find("as a clear coat over a", at + 1))
    ++layering;
  EXPECT_EQ(layering, 3) << said;
  EXPECT_NE(said.find("(line 9) as a clear coat over a diffuse base, eta 1.33 as 1.5, the coat's albedo"),
            std::string::npos)
      << said;
}

TEST(ClearcoatRender, MtlPcAndPcrAreTheCoat) {
  test::ScratchFolder dir;
  dir.write("coat.mtl", "newmtl paint\nKd 0.6 0.1 0.1\nPc 0.9\nPcr 0.2\nnewmtl glass\nillum 7\nNi 1.5\nPc 1\n");
  dir.write("coat.obj", "mtllib coat.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl paint\nf 1 2 3\nusemtl glass\nf 1 3 4\n");
  const Scene s = load_scene((dir / "coat.obj").string());
  const Material* paint = nullptr;
  const Material* glass = nullptr;
  for (const Material& m : s.materials) (m.name == "paint" ? paint : glass) = &m;
  ASSERT_TRUE(paint && glass);
  EXPECT_FLOAT_EQ(paint->clearcoat, 0.9f);
  EXPECT_FLOAT_EQ(paint->clearcoat_roughness, 0.2f);
  EXPECT_FALSE(glass->has_clearcoat());
  bool warned = false;
  for (const std::string& w : s.warnings) warned |= w.find("Pc on glass") != std::string::npos;
  EXPECT_TRUE(warned);
}

// A checkpoint of one coat does not resume as another (renderer.h's fingerprint).
TEST(ClearcoatRender, TheCoatIsPartOfTheImageFingerprint) {
  RenderSettings s;
  s.width = s.height = 4;
  const std::string plain = R"({"name": "floor", "type": "diffuse", "base_color": [0.5, 0.5, 0.5]})";
  const std::string coated = R"({"name": "floor", "type": "diffuse", "base_color": [0.5, 0.5, 0.5],
      "clearcoat": 1, "clearcoat_roughness": 0.2})";
  const std::uint64_t without = image_fingerprint(floor_under_white_sky(plain), s);
  Scene a = floor_under_white_sky(coated);
  const std::uint64_t with = image_fingerprint(a, s);
  EXPECT_NE(with, without);
  a.materials[0].clearcoat_roughness = 0.3f;
  EXPECT_NE(image_fingerprint(a, s), with);
  Scene b = floor_under_white_sky(coated);
  b.materials[0].clearcoat = 0.5f;
  EXPECT_NE(image_fingerprint(b, s), with);
}

}  // namespace
}  // namespace prism
