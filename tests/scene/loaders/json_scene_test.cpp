#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/core/error.h"
#include "prism/io/png.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/json_scene.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

using loaders::parse_json_scene;
using test::error_of;

// A valid scene: one diffuse quad (two triangles, 2 × 1 units) that emits `emission`.
std::string quad_scene(std::string_view material_extra = "", std::string_view top_extra = "") {
  return std::string(R"({
  "format": "prism-scene/1",
  "name": "quad",
  "materials": [
    {"name": "m", "type": "diffuse", "base_color": [0.5, 0.5, 0.5])") +
         std::string(material_extra) + R"(}
  ],
  "meshes": [
    {"name": "q", "material": "m",
     "positions": [[0,0,0], [2,0,0], [2,1,0], [0,1,0]], "indices": [0,1,2, 0,2,3]}
  ])" + std::string(top_extra) +
         "\n}\n";
}

Scene parse_json_text(std::string_view text, const LoadOptions& options = {}) {
  return parse_json_scene(text, "test.json", {}, "test", options);
}

TEST(JsonScene, BuiltinMaterialTestHasEveryMaterialType) {
  const Scene scene = load_scene("material-test");
  EXPECT_EQ(scene.name, "material-test");
  bool seen[5] = {};
  for (const auto& m : scene.materials) seen[static_cast<int>(m.type)] = true;
  for (int t = 0; t < 5; ++t) EXPECT_TRUE(seen[t]) << "material type " << t;
  EXPECT_TRUE(scene.warnings.empty());
  EXPECT_GT(scene.triangle_count(), 1000u);
  EXPECT_GT(scene.camera.f_number, 0.0f);
}

TEST(JsonScene, BuiltinDispersionPrismUsesBk7Sellmeier) {
  const Scene scene = load_scene("dispersion-prism");
  const Material* glass = nullptr;
  for (const auto& m : scene.materials)
    if (m.type == MaterialType::dielectric) glass = &m;
  ASSERT_NE(glass, nullptr);
  EXPECT_EQ(glass->dispersion, DispersionModel::sellmeier);
  // SCHOTT's catalogue value n_d = 1.5168 for N-BK7; the Sellmeier fit reproduces it to 1e-5.
  EXPECT_NEAR(glass->ior, 1.5168f, 2e-5f);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(JsonScene, ReadsGeometryCameraAndRenderSettings) {
  const Scene scene = parse_json_text(quad_scene("", R"(,
  "render": {"width": 64, "height": 32, "spp": 8, "max_depth": 5},
  "camera": {"type": "thin_lens", "eye": [0,0,5], "target": [0,0,0], "fov_degrees": 30,
             "aperture_radius": 0.1, "focus_distance": 4, "exposure": {"f_number": 8, "shutter_seconds": 0.01}})"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.triangle_count(), 2u);
  EXPECT_EQ(scene.default_width, 64);
  EXPECT_EQ(scene.default_spp, 8);
  EXPECT_EQ(scene.default_max_depth, 5);
  EXPECT_FLOAT_EQ(scene.camera.aperture_radius, 0.1f);
  EXPECT_FLOAT_EQ(scene.camera.focus_distance, 4.0f);
  EXPECT_FLOAT_EQ(scene.camera.f_number, 8.0f);
  EXPECT_FLOAT_EQ(scene.camera.iso, 100.0f);
}

TEST(JsonScene, ConvertsPhotometricUnits) {
  // Emission power: Φ = π L A for a one-sided Lambertian emitter of A = 2 m² (units in cm,
  // so 2 units² = 2e-4 m²).
  const Scene scene = parse_json_text(quad_scene(R"(, "emission": {"color": [1,1,1], "power_lm": 100})",
                                       R"(, "meters_per_unit": 0.01,
  "lights": [
    {"type": "point", "position": [0,1,0], "power_lm": 1000},
    {"type": "spot", "position": [0,1,0], "direction": [0,-1,0], "power_lm": 1000,
     "inner_angle_degrees": 20, "outer_angle_degrees": 40},
    {"type": "directional", "direction": [0,-1,0], "illuminance_lux": 100000, "angular_diameter_degrees": 0.53}
  ],
  "environment": {"luminance_nits": 250})"));
  // Relative 1e-6: the area and the result pass through single precision.
  const double nits = 100.0 / (std::numbers::pi * 2e-4);
  EXPECT_NEAR(scene.materials[0].emission.luminance_nits, nits, 1e-6 * nits);
  ASSERT_EQ(scene.lights.size(), 4u);
  EXPECT_NEAR(scene.lights[0].intensity, 1000.0 / (4.0 * std::numbers::pi), 1e-3);
  const double cos_mid = 0.5 * (std::cos(20.0 * std::numbers::pi / 180) + std::cos(40.0 * std::numbers::pi / 180));
  EXPECT_NEAR(scene.lights[1].intensity, 1000.0 / (2.0 * std::numbers::pi * (1.0 - cos_mid)), 1e-2);
  EXPECT_EQ(scene.lights[2].type, LightType::directional);
  EXPECT_FLOAT_EQ(scene.lights[2].intensity, 100000.0f);
  EXPECT_EQ(scene.lights[3].type, LightType::environment);
  EXPECT_FLOAT_EQ(scene.lights[3].intensity, 250.0f);
}

TEST(JsonScene, InstancesTransformsAndSpheres) {
  std::string text = quad_scene("", R"(,
  "instances": [
    {"mesh": "q", "transform": {"translate": [0, 0, 5]}},
    {"mesh": "ball", "transform": {"rotate": {"axis": [0,1,0], "angle_degrees": 90}, "scale": 2}}
  ])");
  text.replace(text.find("\n  ],\n  \"instances\""), 4, R"(,
    {"name": "ball", "material": "m", "shape": "sphere", "center": [0,0,0], "radius": 1, "subdivisions": 4,
     "prototype": true}
  ])");
  const Scene scene = parse_json_text(text);
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[1].triangle_count(), 2u * 4 * 8 - 2 * 8);  // pole bands: one triangle per segment
  // Two explicit instances plus the non-prototype quad placed once in place.
  ASSERT_EQ(scene.instances.size(), 3u);
  EXPECT_FLOAT_EQ(scene.instances[0].object_to_world.translation.z, 5.0f);
  const Vec3f x = scene.instances[1].object_to_world.apply_vector(Vec3f(1, 0, 0));
  EXPECT_NEAR(x.x, 0.0f, 1e-6f);
  EXPECT_NEAR(x.z, -2.0f, 1e-6f);  // 90° about +y takes +x to −z, then scale 2
  EXPECT_EQ(scene.instances[2].mesh, 0u);
}

// A prototype appears only through instances, also in a scene without any: the other
// meshes are placed once, and a scene of prototypes alone is an error, not an empty image.
TEST(JsonScene, PrototypesWithoutInstancesAreNotPlaced) {
  std::string text = quad_scene();
  text.replace(text.find("\n  ]\n}"), 4, R"(,
    {"name": "ball", "material": "m", "shape": "sphere", "center": [0,0,0], "radius": 1, "prototype": true}
  ])");
  const Scene scene = parse_json_text(text);
  ASSERT_EQ(scene.meshes.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 1u);  // the quad alone
  EXPECT_EQ(scene.instances[0].mesh, 0u);
  std::string only = quad_scene();
  only.replace(only.find(R"("indices": [0,1,2, 0,2,3]})"), 29, R"("indices": [0,1,2, 0,2,3], "prototype": true})");
  const std::string message = error_of<SceneError>([&] { parse_json_text(only); });
  EXPECT_NE(message.find("meshes: every mesh is a prototype"), std::string::npos) << message;
}

TEST(JsonScene, MalformedJsonReportsLineAndColumn) {
  const std::string text = "{\n  \"format\": \"prism-scene/1\",\n  \"materials\": [,]\n}\n";
  const std::string message = error_of<SceneError>([&] { parse_json_text(text); });
  EXPECT_NE(message.find("test.json:3:17: malformed JSON"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_NE(error_of<SceneError>([] { parse_json_text(""); }).find("test.json:1:1:"), std::string::npos);
  const std::string full = quad_scene();
  const std::string truncated = full.substr(0, full.size() / 2);
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(truncated); }).find("malformed JSON"), std::string::npos);
}

TEST(JsonScene, NumberTooLargeForADoubleIsMalformedJson) {
  // Regression (fuzz_json_scene): nlohmann throws out_of_range 406, not parse_error, for a
  // number that overflows a double; it escaped as an uncaught exception.
  const std::string text = "{\"format\": \"prism-scene/1\",\n \"meters_per_unit\": 7590048281e8888888}";
  const std::string message = error_of<SceneError>([&] { parse_json_text(text); });
  EXPECT_NE(message.find("test.json:2:21: malformed JSON: "), std::string::npos) << message;
  EXPECT_NE(message.find("number overflow"), std::string::npos) << message;
}

TEST(JsonScene, RenderObjectMayChooseTheNormalMappingModel) {
  EXPECT_FALSE(parse_json_text(quad_scene()).default_normal_mapping.has_value());  // none: the renderer's default
  const Scene micro = parse_json_text(quad_scene("", R"(, "render": {"normal_mapping": "microfacet"})"));
  ASSERT_TRUE(micro.default_normal_mapping.has_value());
  EXPECT_EQ(*micro.default_normal_mapping, NormalMapping::microfacet);
  EXPECT_EQ(parse_json_text(quad_scene("", R"(, "render": {"normal_mapping": "classic"})")).default_normal_mapping,
            NormalMapping::classic);
  const std::string message =
      error_of<SceneError>([] { parse_json_text(quad_scene("", R"(, "render": {"normal_mapping": "bent"})")); });
  EXPECT_NE(message.find("render.normal_mapping: unknown value 'bent' (expected one of: classic, microfacet)"),
            std::string::npos)
      << message;
}

// Two values for one key are a mistake to report, not a choice to make silently.
TEST(JsonScene, DuplicateKeysAreMalformedJson) {
  const std::string message = error_of<SceneError>([] { parse_json_text(quad_scene(R"(, "type": "conductor")")); });
  EXPECT_NE(message.find("test.json:5:69: malformed JSON: duplicate key \"type\""), std::string::npos) << message;
}

TEST(JsonScene, TextPositionCountsLinesAndColumns) {
  EXPECT_EQ(loaders::text_position("ab\ncd", 0).line, 1u);
  EXPECT_EQ(loaders::text_position("ab\ncd", 4).line, 2u);
  EXPECT_EQ(loaders::text_position("ab\ncd", 4).column, 2u);
  EXPECT_EQ(loaders::text_position("ab", 99).column, 3u);
}

TEST(JsonScene, SchemaErrorsNameTheJsonPath) {
  std::string text = R"({"format": "prism-scene/1", "materials": [
    {"name": "a", "type": "diffuse"}, {"name": "b", "type": "mirror"},
    {"name": "c", "type": "conductor", "roughness": "rough"}]})";
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(text); }).find("test.json: materials[2].roughness: expected a number"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([] { parse_json_text(quad_scene(R"(, "roughness": 2)")); }).find("materials[0].roughness"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([] { parse_json_text(R"({"format": "prism-scene/2"})"); }).find("unsupported format"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([] { parse_json_text(R"({"name": "x"})"); }).find("missing required key 'format'"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([] { parse_json_text(R"([1, 2])"); }).find("expected an object"), std::string::npos);
  // The quad's material with one of its members changed.
  const auto changed = [](std::string_view from, std::string_view to) {
    std::string text = quad_scene();
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(changed(R"("type": "diffuse")", R"("type": "velvet")")); })
                .find("unknown value 'velvet'"),
            std::string::npos);
  // Out of single precision (JSON has no NaN/Inf literals; this is the way to get an Inf).
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(changed("[0.5, 0.5, 0.5]", "[1e39, 0, 0]")); })
                .find("materials[0].base_color[0]"),
            std::string::npos);
}

// Array elements carry their array's path and their index, built only for a message:
// every shape of mesh array names the exact number that is wrong.
TEST(JsonScene, ErrorsInMeshArraysNameTheElement) {
  const auto mesh_scene = [](std::string_view positions, std::string_view indices) {
    return std::string(R"({"format": "prism-scene/1", "materials": [{"name": "m", "type": "diffuse"}],
      "meshes": [{"name": "ok", "material": "m", "positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0,1,2]},
                 {"name": "q", "material": "m", "positions": )") +
           std::string(positions) + R"(, "indices": )" + std::string(indices) + "}]}";
  };
  // Flat: the fifth number; nested: the second vertex's third number.
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(mesh_scene("[0,0,0, 1,\"x\",0, 0,1,0]", "[0,1,2]")); })
                .find("test.json: meshes[1].positions[4]: expected a number"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(mesh_scene("[[0,0,0], [1,0,1e39], [0,1,0]]", "[0,1,2]")); })
                .find("test.json: meshes[1].positions[1][2]:"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(mesh_scene("[[0,0,0], [1,0], [0,1,0]]", "[0,1,2]")); })
                .find("meshes[1].positions[1]:"),
            std::string::npos);
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(mesh_scene("[0,0,0, 1,0,0, 0,1,0]", "[0,1,-2]")); })
                .find("test.json: meshes[1].indices[2]:"),
            std::string::npos);
}

TEST(JsonScene, UnknownKeysGiveOneWarning) {
  const Scene scene = parse_json_text(quad_scene(R"(, "sheen": 1, "subsurface": 0.5)", R"(, "extras": {})"));
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("materials[0].sheen"), std::string::npos);
  EXPECT_NE(scene.warnings[0].find("materials[0].subsurface"), std::string::npos);
  EXPECT_NE(scene.warnings[0].find("extras"), std::string::npos);
}

TEST(JsonScene, BadGeometryIsAnErrorAndZeroAreaTrianglesAreDropped) {
  std::string bad_index = quad_scene();
  bad_index.replace(bad_index.find("0,2,3"), 5, "0,2,9");
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(bad_index); }).find("index 9 (at 5) is out of range"), std::string::npos);
  std::string negative = quad_scene();
  negative.replace(negative.find("0,2,3"), 5, "0,2,-1");
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(negative); }).find("meshes[0].indices[5]"), std::string::npos);
  std::string degenerate = quad_scene();
  degenerate.replace(degenerate.find("0,2,3"), 5, "0,2,3, 1,1,2, 0,1,1");
  const Scene scene = parse_json_text(degenerate);
  EXPECT_EQ(scene.triangle_count(), 2u);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("dropped 2 zero-area triangles"), std::string::npos);
  std::string unknown_material = quad_scene();
  unknown_material.replace(unknown_material.find("\"material\": \"m\""), 15, "\"material\": \"z\"");
  EXPECT_NE(error_of<SceneError>([&] { parse_json_text(unknown_material); }).find("no material named 'z'"), std::string::npos);
}

TEST(JsonScene, MissingFileIsAnIoError) {
  test::ScratchFolder dir;
  EXPECT_THROW(load_scene((dir / "nope.json").string()), IoError);
  EXPECT_THROW(loaders::load_json_scene(dir / "nope.json"), IoError);
}

TEST(JsonScene, LoadsAFileWithASharedTextureOnce) {
  test::ScratchFolder dir;
  std::filesystem::create_directories(dir / "tex");
  write_png(dir / "tex" / "checker.png", EncodedImage{2, 2, 3, 8, {255, 255, 255, 0, 0, 0, 0, 0, 0, 255, 255, 255}});
  std::string text = quad_scene(R"(, "base_color_texture": "tex/checker.png")");
  text.replace(text.find("\n  ],\n  \"meshes\""), 4, R"(,
    {"name": "n", "type": "diffuse", "base_color_texture": {"file": "tex/../tex/checker.png", "encoding": "srgb"}}
  ])");
  dir.write("scene.json", text);
  const Scene scene = load_scene((dir / "scene.json").string());
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.materials[0].base_color_texture, 0);
  EXPECT_EQ(scene.materials[1].base_color_texture, 0);
  EXPECT_FLOAT_EQ(scene.textures[0].value(0), 1.0f);
  EXPECT_FLOAT_EQ(scene.textures[0].value(3), 0.0f);
}

TEST(JsonScene, NormalAndBumpTexturesAreLinearWithScales) {
  test::ScratchFolder dir;
  write_png(dir / "normal.png", EncodedImage{1, 1, 3, 8, {128, 128, 255}});
  write_png(dir / "grey.png", EncodedImage{1, 1, 1, 8, {128}});
  dir.write("scene.json", quad_scene(R"(, "normal_texture": "normal.png", "normal_scale": 0.25,
     "bump_texture": "grey.png", "bump_scale": 0.02)"));
  const Scene scene = load_scene((dir / "scene.json").string());
  const Material& m = scene.materials[0];
  ASSERT_GE(m.normal_texture, 0);
  ASSERT_GE(m.bump_texture, 0);
  EXPECT_FLOAT_EQ(m.normal_scale, 0.25f);
  EXPECT_FLOAT_EQ(m.bump_scale, 0.02f);
  EXPECT_FLOAT_EQ(scene.textures[static_cast<std::size_t>(m.normal_texture)].value(0), 128.0f / 255.0f);  // linear
  EXPECT_FLOAT_EQ(scene.textures[static_cast<std::size_t>(m.bump_texture)].value(0), 128.0f / 255.0f);
  dir.write("grey.json", quad_scene(R"(, "normal_texture": "grey.png")"));
  const std::string message = error_of<SceneError>([&] { load_scene((dir / "grey.json").string()); });
  EXPECT_NE(message.find("materials[0].normal_texture"), std::string::npos) << message;
  EXPECT_NE(message.find("RGB"), std::string::npos) << message;
}

TEST(JsonScene, FileReferencesMayNotLeaveTheScenesFolder) {
  test::ScratchFolder dir;
  dir.write("outside.png", "not an image");
  const auto scene_with = [&](std::string_view file) {
    return dir.write("inner/scene.json",
                     quad_scene(R"(, "base_color_texture": ")" + std::string(file) + "\""));
  };
  const auto escape = scene_with("../../../../../../../../etc/passwd");
  std::string message = error_of<SceneError>([&] { load_scene(escape.string()); });
  EXPECT_NE(message.find("materials[0].base_color_texture: path '../../../../../../../../etc/passwd' leads outside"),
            std::string::npos)
      << message;
  const auto absolute = scene_with((dir / "outside.png").string());
  EXPECT_NE(error_of<SceneError>([&] { load_scene(absolute.string()); }).find("absolute path"), std::string::npos);
  // Allowed on request: the file is then read (and here refused as not an image).
  EXPECT_NE(error_of<IoError>([&] { load_scene(absolute.string(), LoadOptions{.allow_external_paths = true}); })
                .find("wrong magic"),
            std::string::npos);
  // A symbolic link inside the folder that leads out is caught too.
  std::filesystem::create_symlink(dir / "outside.png", dir / "inner" / "link.png");
  const auto link = scene_with("link.png");
  EXPECT_NE(error_of<SceneError>([&] { load_scene(link.string()); }).find("leads outside"), std::string::npos);
  // Built-in (embedded) scenes may not refer to files at all.
  EXPECT_NE(error_of<SceneError>([] { parse_json_text(quad_scene(R"(, "base_color_texture": "a.png")")); }).find("built-in"),
            std::string::npos);
}

TEST(JsonScene, EnvironmentMappingIsEquirectangularOrEqualAreaOctahedral) {
  test::ScratchFolder dir;
  write_png(dir / "square.png", EncodedImage{2, 2, 3, 8, std::vector<std::uint16_t>(12, 255)});
  write_png(dir / "wide.png", EncodedImage{4, 2, 3, 8, std::vector<std::uint16_t>(24, 255)});
  const auto with_environment = [&](std::string_view environment) {
    return dir.write("scene.json", quad_scene("", std::string(",\n  \"environment\": ") + std::string(environment)));
  };
  const Scene plain = load_scene(with_environment(R"({"luminance_nits": 1, "texture": "wide.png"})").string());
  EXPECT_EQ(plain.lights[0].environment_mapping, EnvironmentMapping::equirectangular);
  const Scene octahedral = load_scene(
      with_environment(R"({"luminance_nits": 1, "texture": "square.png", "mapping": "equal-area-octahedral"})")
          .string());
  EXPECT_EQ(octahedral.lights[0].environment_mapping, EnvironmentMapping::equal_area_octahedral);
  const std::string wide = error_of<SceneError>([&] {
    load_scene(
        with_environment(R"({"luminance_nits": 1, "texture": "wide.png", "mapping": "equal-area-octahedral"})")
            .string());
  });
  EXPECT_NE(wide.find("environment.mapping"), std::string::npos) << wide;
  EXPECT_NE(wide.find("square"), std::string::npos) << wide;
  EXPECT_THROW(load_scene(with_environment(R"({"luminance_nits": 1, "mapping": "cube"})").string()), SceneError);
}

}  // namespace
}  // namespace prism
