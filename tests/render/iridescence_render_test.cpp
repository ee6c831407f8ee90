// Iridescence end to end (bsdf/thin_film.h): a filmed floor under a white sky shows the
// film's reflectance at the transport's wavelengths; the JSON keys and their rules; glTF's
// KHR_materials_iridescence; the writers (JSON and GLB keep it, pbrt-v4 refuses it); the
// image fingerprint and `prism info`.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/bsdf/thin_film.h"
#include "prism/color/cie_1931.h"
#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/loaders/gltf_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"
#include "scene/loaders/loader_test_files.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"
#include "support/floor_under_sky.h"
#include "support/one_triangle_gltf.h"
#include "support/write_and_reload.h"

namespace prism {
namespace {

using test::floor_under_white_sky;

constexpr double kFilmEta = 2.0, kBaseEta = 1.5, kThicknessNm = 300.0;

// A black, nearly smooth (roughness 0.1) metallic_roughness floor under a full film
// (weight 1) of η 2 and 300 nm over its η 1.5 seen straight down reflects the film's
// R(λ, cos θ = 1) of the white sky. RGB transport: the working space's channels are R at
// 630, 532 and 465 nm. Spectral: the sky is an equal-energy spectrum, so the film's Y is
// ∫ R ȳ / ∫ ȳ (trapezoid, 1 nm). The bound: 5σ of the film's noise plus 2e-3 for the lobe's
// width (as tests/render/specular_layer_render_test.cpp). Without the film the floor would
// reflect 0.04 in every channel; with it the channels get 0.057, 0.134 and 0.198.
TEST(IridescenceRender, FilmedFloorShowsTheFilmsReflectance) {
  const Scene scene = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "base_color": [0, 0, 0],
      "roughness": 0.1, "ior": 1.5, "iridescence": 1, "iridescence_ior": 2, "iridescence_thickness_max_nm": 300})");
  const auto film = [](double nm) { return bsdf::thin_film_reflectance(1.0, nm, kThicknessNm, kFilmEta, kBaseEta); };
  const test::BlockEstimate rgb = test::block_estimate(
      render(scene, test::direct_light_settings(TransportKind::rgb, LightEstimator::mis, 64, 5)).film, 0, 0, 8, 8);
  const double expected_rgb[3] = {film(630.0), film(532.0), film(465.0)};
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(rgb.mean[c], expected_rgb[c], 5.0 * std::sqrt(rgb.variance[c]) + 2e-3) << "rgb channel " << c;
  EXPECT_GT(expected_rgb[2] - expected_rgb[0], 0.1);  // the film is coloured here
  double weighted = 0.0, weight = 0.0;
  for (int nm = 380; nm <= 780; ++nm) {
    const double w = (nm == 380 || nm == 780 ? 0.5 : 1.0) * color::cie1931_y_bar(nm);
    weighted += w * film(nm);
    weight += w;
  }
  const test::BlockEstimate spectral = test::block_estimate(
      render(scene, test::direct_light_settings(TransportKind::spectral, LightEstimator::mis, 256, 5)).film, 0, 0, 8, 8);
  EXPECT_NEAR(spectral.mean.y, weighted / weight, 5.0 * std::sqrt(spectral.variance.y) + 2e-3);
}

TEST(IridescenceRender, JsonKeysAndTheirRules) {
  const auto error = [](const std::string& material) {
    return test::error_of<SceneError>([&] { floor_under_white_sky(material); });
  };
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "iridescence": 1})")
                .find("materials[0].iridescence: only metallic_roughness materials take a thin film"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "metallic_roughness", "iridescence_ior": 1.4})")
                .find("materials[0].iridescence_ior: give 'iridescence'"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "metallic_roughness", "iridescence": 2})").find("materials[0].iridescence"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "metallic_roughness", "iridescence": 1, "iridescence_ior": 0.5})")
                .find("materials[0].iridescence_ior"),
            std::string::npos);
  const Scene s = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "iridescence": 0.7,
      "iridescence_ior": 1.4, "iridescence_thickness_min_nm": 50, "iridescence_thickness_max_nm": 600})");
  const Material& m = s.materials[0];
  EXPECT_TRUE(m.has_iridescence());
  EXPECT_FLOAT_EQ(m.iridescence, 0.7f);
  EXPECT_FLOAT_EQ(m.iridescence_ior, 1.4f);
  EXPECT_FLOAT_EQ(m.iridescence_thickness_min_nm, 50.0f);
  EXPECT_FLOAT_EQ(m.iridescence_thickness_max_nm, 600.0f);
  const std::string summary = format_scene_summary(s);
  EXPECT_NE(summary.find("1 iridescent"), std::string::npos) << summary;
}

Scene gltf_with_material(const std::string& material) {
  return test::one_triangle_gltf(material, "KHR_materials_iridescence");
}

TEST(IridescenceRender, GltfFactorsDefaultsAndRules) {
  const Scene s = gltf_with_material(R"({"extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 0.5,
      "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 200, "iridescenceThicknessMaximum": 700}}})");
  const Material& m = s.materials[0];
  EXPECT_TRUE(m.has_iridescence());
  EXPECT_FLOAT_EQ(m.iridescence, 0.5f);
  EXPECT_FLOAT_EQ(m.iridescence_ior, 1.8f);
  EXPECT_FLOAT_EQ(m.iridescence_thickness_min_nm, 200.0f);
  EXPECT_FLOAT_EQ(m.iridescence_thickness_max_nm, 700.0f);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("KHR_materials_iridescence"), std::string::npos) << w;
  // The extension's defaults: η 1.3, 100–400 nm; factor 0 is no film.
  const Scene defaults = gltf_with_material(R"({"extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 1}}})");
  const Material& d = defaults.materials[0];
  EXPECT_FLOAT_EQ(d.iridescence_ior, 1.3f);
  EXPECT_FLOAT_EQ(d.iridescence_thickness_min_nm, 100.0f);
  EXPECT_FLOAT_EQ(d.iridescence_thickness_max_nm, 400.0f);
  EXPECT_FALSE(gltf_with_material(R"({"extensions": {"KHR_materials_iridescence": {}}})").materials[0].has_iridescence());
  // specularFactor 0 (Lambert alone) keeps its film: metallic_roughness with a layer of weight 0.
  const Scene lambert_scene = gltf_with_material(R"({"pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_specular": {"specularFactor": 0}, "KHR_materials_iridescence": {"iridescenceFactor": 1}}})");
  const Material& lambert = lambert_scene.materials[0];
  EXPECT_TRUE(lambert.has_iridescence());
  EXPECT_EQ(lambert.specular, 0.0f);
  const Scene glass = gltf_with_material(R"({"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_iridescence": {"iridescenceFactor": 1}}})");
  EXPECT_FALSE(glass.materials[0].has_iridescence());
  bool said = false;
  for (const std::string& w : glass.warnings)
    said |= w.find("materials[0].extensions.KHR_materials_iridescence: ignored on a transmitting material") !=
            std::string::npos;
  EXPECT_TRUE(said);
  for (const auto& [film, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"({"iridescenceFactor": 1.5})", "iridescenceFactor must be in [0, 1]"},
           {R"({"iridescenceFactor": 1, "iridescenceIor": 0.9})", "iridescenceIor must be between 1 and 10"},
           {R"({"iridescenceFactor": 1, "iridescenceThicknessMaximum": -5})",
            "iridescenceThicknessMinimum and Maximum must be in [0, 100000] nm"}}) {
    const std::string material = R"({"extensions": {"KHR_materials_iridescence": )" + film + "}}";
    const std::string message = test::error_of<SceneError>([&] { gltf_with_material(material); });
    EXPECT_NE(message.find("materials[0].extensions.KHR_materials_iridescence: " + expected), std::string::npos)
        << film << " → " << message;
  }
}

// JSON and GLB keep the film; pbrt-v4 has none: its writer refuses the scene in one line
// before writing anything.
TEST(IridescenceRender, WritersKeepTheFilmOrRefuseIt) {
  const Scene original = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "iridescence": 0.6,
      "iridescence_ior": 1.45, "iridescence_thickness_min_nm": 120, "iridescence_thickness_max_nm": 480})");
  test::ScratchFolder dir;
  for (const char* name : {"floor.json", "floor.glb"}) {
    const Scene loaded = test::write_and_reload(original, dir / name);
    const Material& m = loaded.materials[loaded.meshes[0].material];
    EXPECT_FLOAT_EQ(m.iridescence, 0.6f) << name;
    EXPECT_FLOAT_EQ(m.iridescence_ior, 1.45f) << name;
    EXPECT_FLOAT_EQ(m.iridescence_thickness_min_nm, 120.0f) << name;
    EXPECT_FLOAT_EQ(m.iridescence_thickness_max_nm, 480.0f) << name;
  }
  const std::string message =
      test::error_of<UsageError>([&] { loaders::write_scene_pbrt(original, dir / "floor.pbrt"); });
  EXPECT_NE(message.find("pbrt writer: material 'floor' has a thin film (iridescence)"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(dir / "floor.pbrt"));
}

// A checkpoint of one film does not resume as another (renderer.h's fingerprint).
TEST(IridescenceRender, TheFilmIsPartOfTheImageFingerprint) {
  RenderSettings s;
  s.width = s.height = 4;
  const std::string filmed = R"({"name": "floor", "type": "metallic_roughness", "iridescence": 1})";
  const std::uint64_t without =
      image_fingerprint(floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness"})"), s);
  Scene a = floor_under_white_sky(filmed);
  const std::uint64_t with = image_fingerprint(a, s);
  EXPECT_NE(with, without);
  a.materials[0].iridescence_thickness_max_nm = 500.0f;
  EXPECT_NE(image_fingerprint(a, s), with);
  Scene b = floor_under_white_sky(filmed);
  b.materials[0].iridescence_ior = 1.5f;
  EXPECT_NE(image_fingerprint(b, s), with);
}

}  // namespace
}  // namespace prism
