// prism-scene/1 spectra: emitters and reflectances given as data (json_scene_spectra.cpp).
#include <gtest/gtest.h>

#include "prism/color/illuminants.h"
#include "prism/core/error.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"
#include "prism/scene/spectral_inputs.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

using test::error_of;

// One quad with material `material` (its members after the name) and `lights`.
std::string scene_with(std::string_view material, std::string_view lights = "[]") {
  return std::string(R"({"format": "prism-scene/1", "name": "s",
  "materials": [{"name": "m", "type": "diffuse", )") +
         std::string(material) + R"(}],
  "lights": )" + std::string(lights) + R"(,
  "meshes": [{"name": "q", "material": "m", "positions": [[0,0,0], [1,0,0], [1,1,0]], "indices": [0,1,2]}]})";
}

Scene parse_spectra_json(std::string_view text) { return loaders::parse_json_scene(text, "test.json", {}, "test", {}); }

std::string spectra_parse_error(std::string_view text) {
  return error_of<SceneError>([&] { parse_spectra_json(text); });
}

TEST(JsonSceneSpectra, EmittersTakeNamedBlackbodyAndTabulatedSpectra) {
  const Scene named = parse_spectra_json(scene_with(R"("emission": {"spectrum": "F11", "luminance_nits": 10})"));
  const Emission& e = named.materials[0].emission;
  ASSERT_TRUE(e.spectrum);
  EXPECT_EQ(*e.spectrum, *named_emission_spectrum("F11"));
  EXPECT_EQ(e.color, emission_spectrum_srgb(*e.spectrum));  // the RGB approximation
  EXPECT_TRUE(named.materials[0].is_emissive());

  const Scene hot = parse_spectra_json(scene_with(R"("emission": {"spectrum": {"blackbody_k": 2856}, "luminance_nits": 10})"));
  EXPECT_EQ(*hot.materials[0].emission.spectrum, blackbody_emission_spectrum(2856.0));

  const Scene points = parse_spectra_json(scene_with(
      R"("emission": {"spectrum": {"wavelengths_nm": [400, 500, 600, 700], "values": [0, 8, 15.6, 18.4]},
                      "luminance_nits": 10})"));
  const auto& s = *points.materials[0].emission.spectrum;
  EXPECT_DOUBLE_EQ(s(550.0), 11.8);
  EXPECT_DOUBLE_EQ(s(750.0), 18.4);  // held past the last point

  const Scene light = parse_spectra_json(scene_with(R"("base_color": [0.5, 0.5, 0.5])",
                                       R"([{"type": "point", "position": [0, 1, 0], "intensity_cd": 5,
                                            "spectrum": "A"}])"));
  ASSERT_TRUE(light.lights[0].spectrum);
  EXPECT_EQ(*light.lights[0].spectrum, *named_emission_spectrum("A"));
  EXPECT_GT(light.lights[0].color.x, light.lights[0].color.z);  // orange
  const std::string summary = format_scene_summary(light);
  EXPECT_NE(summary.find("lights 1 (1 point; 1 with spectra)"), std::string::npos) << summary;
}

TEST(JsonSceneSpectra, ReflectancesAreMeasuredData) {
  const Scene scene = parse_spectra_json(scene_with(
      R"("base_color_spectrum": {"wavelengths_nm": [400, 550, 700], "values": [0.1, 0.5, 0.8]})"));
  const Material& m = scene.materials[0];
  ASSERT_TRUE(m.base_color_spectrum);
  EXPECT_DOUBLE_EQ((*m.base_color_spectrum)(475.0), 0.3);
  EXPECT_EQ(m.base_color, reflectance_spectrum_srgb(*m.base_color_spectrum));
  EXPECT_GT(m.base_color.x, m.base_color.z);  // rising towards red
}

TEST(JsonSceneSpectra, CsvColumnsAreReadByName) {
  test::ScratchFolder dir;
  dir.write("walls.csv", "wavelength_nm,white,red\n# measured\n400,0.343,0.040\n\n500,0.747,0.061\n700,0.733,0.642\n");
  dir.write("scene.json", scene_with(R"("base_color_spectrum": {"file": "walls.csv", "column": "red"})"));
  const Scene scene = load_scene((dir / "scene.json").string());
  const auto& red = *scene.materials[0].base_color_spectrum;
  ASSERT_EQ(red.values().size(), 3u);
  EXPECT_DOUBLE_EQ(red(700.0), 0.642);
  dir.write("first.json", scene_with(R"("base_color_spectrum": {"file": "walls.csv"})"));
  EXPECT_DOUBLE_EQ((*load_scene((dir / "first.json").string()).materials[0].base_color_spectrum)(400.0), 0.343);

  dir.write("bad.csv", "wavelength_nm,white\n400,0.3\n500,x\n");
  dir.write("bad.json", scene_with(R"("base_color_spectrum": {"file": "bad.csv"})"));
  std::string message = error_of<SceneError>([&] { load_scene((dir / "bad.json").string()); });
  EXPECT_NE(message.find("materials[0].base_color_spectrum.file"), std::string::npos) << message;
  EXPECT_NE(message.find("bad.csv:3: 'x' is not a finite number"), std::string::npos) << message;
  dir.write("column.json", scene_with(R"("base_color_spectrum": {"file": "walls.csv", "column": "green"})"));
  message = error_of<SceneError>([&] { load_scene((dir / "column.json").string()); });
  EXPECT_NE(message.find("walls.csv:1: no column named 'green'"), std::string::npos) << message;
  dir.write("missing.json", scene_with(R"("base_color_spectrum": {"file": "nope.csv"})"));
  message = error_of<SceneError>([&] { load_scene((dir / "missing.json").string()); });
  EXPECT_NE(message.find("cannot read spectrum"), std::string::npos) << message;
}

// The writers are for generated RGB scenes: a spectrum is refused, not dropped.
TEST(JsonSceneSpectra, WritersRefuseSpectraInsteadOfDroppingThem) {
  test::ScratchFolder dir;
  const Scene scene = parse_spectra_json(scene_with(R"("emission": {"spectrum": "F11", "luminance_nits": 10})"));
  for (const auto& write : {&loaders::write_scene_json, &loaders::write_scene_pbrt, &loaders::write_scene_glb}) {
    const std::string message = error_of<UsageError>([&] { write(scene, dir / "out"); });
    EXPECT_NE(message.find("material 'm' has a spectrum"), std::string::npos) << message;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(JsonSceneSpectra, RejectsSpectraThatCannotBe) {
  const struct {
    std::string text, expected;
  } cases[] = {
      {scene_with(R"("emission": {"spectrum": "F13", "luminance_nits": 1})"), "unknown spectrum 'F13'"},
      {scene_with(R"("emission": {"spectrum": "A", "color": [1, 1, 1], "luminance_nits": 1})"),
       "either 'color' or 'spectrum'"},
      {scene_with(R"("base_color": [1, 1, 1],
                     "base_color_spectrum": {"wavelengths_nm": [400, 500], "values": [1, 1]})"),
       "either 'base_color' or 'base_color_spectrum'"},
      {scene_with(R"("base_color_spectrum": "D65")"), "a reflectance spectrum is data"},
      {scene_with(R"("base_color_spectrum": {"blackbody_k": 3000})"), "cannot be a black body"},
      {scene_with(R"("base_color_spectrum": {"wavelengths_nm": [400, 500], "values": [0.5, 1.5]})"),
       "reflectance 1.5 at 500 nm is above 1"},
      {scene_with(R"("base_color_spectrum": {"wavelengths_nm": [500, 400], "values": [0.5, 0.5]})"),
       "wavelengths must increase"},
      {scene_with(R"("base_color_spectrum": {"wavelengths_nm": [400, 500, 600], "values": [0.5, 0.5]})"),
       "3 wavelengths but 2 values"},
      {scene_with(R"("base_color_spectrum": {"wavelengths_nm": [400], "values": [0.5]})"), "at least 2 points"},
      {scene_with(R"("base_color_spectrum": {"wavelengths_nm": [0.4, 0.5], "values": [0.5, 0.5]})"),
       "outside [100, 3000] nm"},
      {scene_with(R"("emission": {"spectrum": {"wavelengths_nm": [400, 500], "values": [1, -1]},
                                  "luminance_nits": 1})"),
       "negative value -1 at 500 nm"},
      {scene_with(R"("emission": {"spectrum": {"wavelengths_nm": [900, 1000], "values": [0, 0]},
                                  "luminance_nits": 1})"),
       "emits no visible light"},
      {scene_with(R"("emission": {"spectrum": {"blackbody_k": 2000, "file": "x.csv"}, "luminance_nits": 1})"),
       "give one of"},
      {scene_with(R"("base_color": [0.5, 0.5, 0.5])", R"([{"type": "point", "position": [0, 1, 0], "intensity_cd": 5,
                                                          "spectrum": "A", "color_space": "acescg"}])"),
       "either 'color' or 'spectrum'"},
  };
  for (const auto& c : cases) {
    const std::string message = spectra_parse_error(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << message;
    EXPECT_NE(message.find("test.json: "), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace prism
