// Dispersive glass in every scene format: JSON's Abbe-number glass, glTF's
// KHR_materials_dispersion, pbrt-v4's sampled "spectrum eta", and the three writers, which
// must bring a dispersive glass back dispersive (they used to write its n_d alone).
#include <gtest/gtest.h>

#include <string>

#include "prism/bsdf/ior.h"
#include "prism/core/error.h"
#include "prism/scene/dielectric_ior.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_scene.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "scene/loaders/loader_test_files.h"
#include "support/floor_under_sky.h"
#include "support/write_and_reload.h"

namespace prism {
namespace {

// Coefficients are held in float: A ≈ 1.5 to 6e-8 relative and B ≈ 0.01 µm² likewise, so
// an index computed from them is good to ≈ 2e-7.
constexpr double kFloatIndex = 2e-7;

TEST(DispersionFormats, JsonGlassOfAnAbbeNumber) {
  const Scene s = test::floor_under_white_sky(
      R"({"name": "floor", "type": "dielectric", "dispersion": {"n_d": 1.6, "abbe_number": 30}})");
  const Material& m = s.materials[0];
  EXPECT_EQ(m.dispersion, DispersionModel::cauchy);
  EXPECT_FLOAT_EQ(m.ior, 1.6f);
  EXPECT_NEAR(dielectric_ior(m, 587.56), 1.6, kFloatIndex);
  // n_F − n_C = 0.6/30 = 0.02: V_d to 2e-7 · 2 / 0.02 relative.
  EXPECT_NEAR(dielectric_abbe_number(m), 30.0, 30.0 * 2e-5);
  // A model key beside the Abbe number is not read: said, as for any unknown key.
  const Scene extra = test::floor_under_white_sky(
      R"({"name": "floor", "type": "dielectric", "dispersion": {"n_d": 1.6, "abbe_number": 30, "model": "cauchy"}})");
  bool said = false;
  for (const std::string& w : extra.warnings) said |= w.find("materials[0].dispersion.model") != std::string::npos;
  EXPECT_TRUE(said);
  for (const auto& [dispersion, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"({"n_d": 1.6, "abbe_number": 0.5})", "abbe_number: 0.5 is out of range"},
           {R"({"n_d": 0.9, "abbe_number": 30})", "n_d: 0.9 is out of range"},
           {R"({"abbe_number": 30})", "n_d"}}) {
    const std::string material = R"({"name": "floor", "type": "dielectric", "dispersion": )" + dispersion + "}";
    const std::string message = test::error_of<SceneError>([&] { test::floor_under_white_sky(material); });
    EXPECT_NE(message.find(expected), std::string::npos) << dispersion << " → " << message;
  }
}

// A one-triangle glTF document whose materials are `materials`.
std::string gltf_with(const std::string& materials) {
  return R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_dispersion"],
    "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA", "byteLength": 36}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "materials": )" + materials + R"(, "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
}

Scene parse_gltf(const std::string& text) {
  return loaders::parse_gltf_scene({reinterpret_cast<const unsigned char*>(text.data()), text.size()}, "test.gltf",
                                   {}, {});
}

// KHR_materials_dispersion: dispersion = 20/V_d on the glass that transmission and ior make.
TEST(DispersionFormats, GltfDispersionIsTheAbbeNumbersCauchyGlass) {
  const Scene s = parse_gltf(gltf_with(R"([
    {"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.7},
                    "KHR_materials_volume": {"thicknessFactor": 1}, "KHR_materials_dispersion": {"dispersion": 0.5}}},
    {"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_dispersion": {}}},
    {"extensions": {"KHR_materials_dispersion": {"dispersion": 1}}}])"));
  ASSERT_EQ(s.materials.size(), 3u);
  const Material& glass = s.materials[0];
  EXPECT_EQ(glass.type, MaterialType::dielectric);
  EXPECT_EQ(glass.dispersion, DispersionModel::cauchy);
  EXPECT_NEAR(dielectric_ior(glass, 587.56), 1.7, kFloatIndex);
  EXPECT_NEAR(dielectric_abbe_number(glass), 40.0, 40.0 * 2e-5);  // 20/0.5; n_F − n_C = 0.0175
  // The extension's closed form, to its rounding of 1.5168 (bsdf test CauchyGlassOfAnAbbeNumberIsTheGltfOne).
  for (const double nm : {400.0, 700.0})
    EXPECT_NEAR(dielectric_ior(glass, nm), 1.7 + 0.7 / 40.0 * (523655.0 / (nm * nm) - 1.5168), 0.7 / 40.0 * 5e-5 + kFloatIndex);
  EXPECT_EQ(s.materials[1].dispersion, DispersionModel::none);  // dispersion defaults to 0
  EXPECT_EQ(s.materials[2].type, MaterialType::metallic_roughness);
  int warned = 0;
  for (const std::string& w : s.warnings)
    warned += w.find("materials[2].extensions.KHR_materials_dispersion: ignored on a material that does not transmit") !=
              std::string::npos;
  EXPECT_EQ(warned, 1);
  const std::string message = test::error_of<SceneError>([&] {
    parse_gltf(gltf_with(R"([{"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                                "KHR_materials_dispersion": {"dispersion": -0.1}}}])"));
  });
  EXPECT_NE(message.find("materials[0].extensions.KHR_materials_dispersion: dispersion must be finite and ≥ 0"),
            std::string::npos)
      << message;
}

Scene parse_pbrt(const std::string& material) {
  return loaders::parse_pbrt_scene("WorldBegin\n" + material +
                                       "\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n",
                                   "test.pbrt", {});
}

// pbrt-v4's dielectric with (λ, η) pairs: the Cauchy glass closest to them, said when it is
// more than 0.001 off somewhere. pbrt-v4 accepts such a spectrum; Prism used to refuse it.
TEST(DispersionFormats, PbrtSampledEtaIsItsClosestCauchyGlass) {
  const Scene cauchy = parse_pbrt(
      R"(Material "dielectric" "spectrum eta" [ 400 1.56875 500 1.544 600 1.530555556 700 1.522448980 ])");  // 1.5 + 0.011/λ²
  const Material& m = cauchy.materials[cauchy.meshes[0].material];
  EXPECT_EQ(m.dispersion, DispersionModel::cauchy);
  EXPECT_NEAR(m.dispersion_coefficients[0], 1.5, 1e-6);
  EXPECT_NEAR(m.dispersion_coefficients[1], 0.011, 1e-6);
  EXPECT_NEAR(m.ior, 1.5 + 0.011 / (0.58756 * 0.58756), 1e-6);
  for (const std::string& w : cauchy.warnings) EXPECT_EQ(w.find("Cauchy"), std::string::npos) << w;
  // A kink no Cauchy glass has: approximated, and said so with the line.
  const Scene kinked = parse_pbrt(R"(Material "dielectric" "spectrum eta" [ 400 1.6 550 1.5 700 1.6 ])");
  bool said = false;
  for (const std::string& w : kinked.warnings)
    said |= w.find("dielectric (line 2) sampled eta as the Cauchy glass closest to it") != std::string::npos;
  EXPECT_TRUE(said);
  for (const auto& [eta, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {"[ 400 1.5 500 ]", "expected (wavelength, index) pairs"},
           {"[ 500 1.5 400 1.6 ]", "increasing"},
           {"[ 400 0.5 500 0.5 ]", "indices must be between 1 and 10"}}) {
    const std::string material = "Material \"dielectric\" \"spectrum eta\" " + eta;
    const std::string message = test::error_of<SceneError>([&] { parse_pbrt(material); });
    EXPECT_NE(message.find(expected), std::string::npos) << eta << " → " << message;
    EXPECT_NE(message.find("test.pbrt:2"), std::string::npos) << message;
  }
}

// Each writer brings a dispersive glass back dispersive: JSON by its model's coefficients
// (exact), pbrt-v4 by pbrt's "glass-BK7" or by (λ, η) pairs that its reader fits (exact for
// a Cauchy glass, within 0.001 for a Sellmeier one), GLB by glTF's 20/V_d (exact for a
// Cauchy glass of its n_d; a Sellmeier glass comes back as the Cauchy glass of its n_d and
// V_d, within 0.001 of it across the visible for N-BK7).
TEST(DispersionFormats, EveryWriterKeepsTheDispersion) {
  const Scene cauchy = test::floor_under_white_sky(
      R"({"name": "floor", "type": "dielectric", "dispersion": {"model": "cauchy", "coefficients": [1.52, 0.012]}})");
  const Scene bk7 = test::floor_under_white_sky(R"({"name": "floor", "type": "dielectric", "dispersion": "N-BK7"})");
  const Scene silica = test::floor_under_white_sky(
      R"({"name": "floor", "type": "dielectric", "dispersion": "fused-silica", "thin_walled": true})");
  test::ScratchFolder dir;
  for (const Scene* scene : {&cauchy, &bk7, &silica})
    for (const char* name : {"floor.json", "floor.glb", "floor.pbrt"}) {
      const std::filesystem::path path = dir / name;
      const Scene loaded = test::write_and_reload(*scene, path);
      const Material& m = loaded.materials[loaded.meshes[0].material];
      const Material& m0 = scene->materials[0];
      const std::string what = m0.name + (m0.dispersion == DispersionModel::sellmeier ? " sellmeier " : " cauchy ") + name;
      EXPECT_EQ(m.type, MaterialType::dielectric) << what;
      EXPECT_EQ(m.thin_walled, m0.thin_walled) << what;
      ASSERT_NE(m.dispersion, DispersionModel::none) << what;
      const bool exact = path.extension() == ".json" || m0.dispersion == DispersionModel::cauchy ||
                         (path.extension() == ".pbrt" && scene == &bk7);
      // Exact: float coefficients and the writers' shortest round-trip decimals. Otherwise
      // a Sellmeier glass as a Cauchy one: the pbrt-v4 reader's 0.001.
      const double tolerance = exact ? 1e-6 : 1e-3;
      for (const double nm : {380.0, 486.13, 587.56, 656.27, 780.0})
        EXPECT_NEAR(dielectric_ior(m, nm), dielectric_ior(m0, nm), tolerance) << what << " at " << nm << " nm";
      EXPECT_NEAR(m.ior, m0.ior, tolerance) << what;
    }
}

}  // namespace
}  // namespace prism
