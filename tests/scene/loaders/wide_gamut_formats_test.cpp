// Wide-gamut colours in every format (Material::base_color_space): the JSON keys, pbrt-v4's
// ColorSpace directive (graphics state, scoped by AttributeBegin/End, for reflectances,
// lights and constant textures), and the writers' round trips. glTF 2.0 holds Rec.709 only:
// its writer converts what lies inside and refuses what lies outside, never clips.
#include <gtest/gtest.h>

#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/emission.h"
#include "prism/scene/scene_summary.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "loader_test_files.h"
#include "support/scratch_folder.h"
#include "support/test_scenes.h"
#include "support/write_and_reload.h"

namespace prism::loaders {
namespace {

// A Rec.2020 green no Rec.709 reflectance reaches (its Rec.709 red is −0.27).
const Vec3f kRec2020Green{0.05f, 0.6f, 0.05f};

Mat3 conversion(const char* from, const char* to) {
  return color::conversion_matrix(color::color_space(from), color::color_space(to));
}

void expect_near(const Vec3f& a, const Vec3f& b, float tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

const Material& mesh_material(const Scene& scene, std::size_t mesh) {
  return scene.materials[scene.meshes[mesh].material];
}

std::string json_scene(const std::string& material) {
  return R"({"format": "prism-scene/1", "name": "q", "materials": [)" + material +
         R"(], "meshes": [{"name": "q", "material": "m", "positions": [[0,0,0], [1,0,0], [0,1,0]],
             "uvs": [[0,0], [1,0], [0,1]], "indices": [0,1,2]}]})";
}

TEST(WideGamutFormats, JsonBaseColourSpaceIsReadAndChecked) {
  const Scene scene = parse_json_scene(
      json_scene(R"({"name": "m", "type": "diffuse", "base_color": [0.05, 0.6, 0.05], "base_color_space": "rec2020"})"),
      "test.json", {}, "test", {});
  EXPECT_EQ(scene.materials[0].base_color_space, ColorPickerSpace::rec2020);
  EXPECT_EQ(scene.materials[0].base_color, kRec2020Green);
  const std::string unknown = test::error_of<SceneError>([] {
    parse_json_scene(json_scene(R"({"name": "m", "type": "diffuse", "base_color_space": "prophoto"})"), "test.json", {},
                     "test", {});
  });
  EXPECT_NE(unknown.find("base_color_space"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("prophoto"), std::string::npos) << unknown;
  // A measured reflectance is a spectrum: it has no primaries to be in.
  const std::string measured = test::error_of<SceneError>([] {
    parse_json_scene(json_scene(R"({"name": "m", "type": "diffuse", "base_color_space": "acescg",
                                    "base_color_spectrum": {"points": [[400, 0.5], [700, 0.5]]}})"),
                     "test.json", {}, "test", {});
  });
  EXPECT_NE(measured.find("not both"), std::string::npos) << measured;
}

Scene wide_gamut_scene() {
  Scene scene;
  scene.name = "wide";
  Material diffuse;
  diffuse.name = "green";
  diffuse.base_color = kRec2020Green;
  diffuse.base_color_space = ColorPickerSpace::rec2020;
  Material metal;
  metal.name = "gold";
  metal.type = MaterialType::conductor;
  metal.base_color = Vec3f(0.9f, 0.6f, 0.2f);
  metal.base_color_space = ColorPickerSpace::acescg;
  Material lamp;
  lamp.name = "lamp";
  lamp.base_color = Vec3f(0.5f);
  lamp.emission.color = Vec3f(0.2f, 0.3f, 0.9f);
  lamp.emission.color_space = ColorPickerSpace::acescg;
  lamp.emission.luminance_nits = 40.0f;
  scene.materials = {diffuse, metal, lamp};
  for (std::uint32_t i = 0; i < 3; ++i) {
    TriangleMesh mesh = test::make_uv_triangle();
    mesh.name = "triangle" + std::to_string(i);
    mesh.material = i;
    for (Vec3f& p : mesh.positions) p.z = static_cast<float>(i);
    scene.meshes.push_back(mesh);
  }
  Light sky;
  sky.type = LightType::environment;
  sky.name = "sky";
  sky.color = Vec3f(0.1f, 0.2f, 0.8f);
  sky.color_space = ColorPickerSpace::rec2020;
  sky.intensity = 3.0f;
  scene.lights.push_back(sky);
  return scene;
}

// What a written scene must give back: the spaces and colours of wide_gamut_scene(). The
// pbrt writer says ACEScg in ACES2065-1 (pbrt-v4 has no ACEScg) and the luminance through
// relative_luminance: float round-off of a 3×3 conversion there and back, 1e-5.
void expect_wide_gamut_scene(const Scene& back, const std::string& file) {
  const Scene original = wide_gamut_scene();
  for (std::size_t i = 0; i < 2; ++i) {
    const Material& m = mesh_material(back, i);
    EXPECT_EQ(m.base_color_space, original.materials[i].base_color_space) << file << " " << i;
    expect_near(m.base_color, original.materials[i].base_color, 1e-5f, file);
  }
  const Material& lamp = mesh_material(back, 2);
  EXPECT_EQ(lamp.emission.color_space, ColorPickerSpace::acescg) << file;
  // Colours are kept up to a scale (pbrt's "rgb L" carries the luminance): compare
  // chromaticities and luminances.
  const Vec3f c = lamp.emission.color / max_component(lamp.emission.color);
  expect_near(c, Vec3f(0.2f, 0.3f, 0.9f) / 0.9f, 1e-5f, file);
  const double nits = lamp.emission.luminance_nits;
  EXPECT_NEAR(nits, 40.0, 40.0 * 1e-5) << file;
  ASSERT_EQ(back.lights.size(), 1u) << file;
  EXPECT_EQ(back.lights[0].color_space, ColorPickerSpace::rec2020) << file;
  expect_near(back.lights[0].color / max_component(back.lights[0].color), Vec3f(0.125f, 0.25f, 1.0f), 1e-5f, file);
}

TEST(WideGamutFormats, JsonAndPbrtWritersKeepEverySpace) {
  test::ScratchFolder dir;
  for (const char* file : {"scene.json", "scene.pbrt"})
    expect_wide_gamut_scene(test::write_and_reload(wide_gamut_scene(), dir / file), file);
}

TEST(WideGamutFormats, PbrtWriterSaysAcescgAsAces2065AndScopesAreaLightSpaces) {
  test::ScratchFolder dir;
  write_scene_pbrt(wide_gamut_scene(), dir / "scene.pbrt");
  const std::string text = test::read_bytes(dir / "scene.pbrt");
  EXPECT_NE(text.find("ColorSpace \"rec2020\""), std::string::npos) << text;
  EXPECT_NE(text.find("ColorSpace \"aces2065-1\""), std::string::npos) << text;
  EXPECT_EQ(text.find("acescg"), std::string::npos) << "pbrt-v4 has no ACEScg";
}

TEST(WideGamutFormats, GlbWriterConvertsWhatRec709HoldsAndRefusesTheRest) {
  test::ScratchFolder dir;
  Scene scene = wide_gamut_scene();
  scene.lights.clear();  // the GLB writer writes no environment
  scene.materials[2].emission.color_space = ColorPickerSpace::srgb;
  // The ACEScg gold lies inside Rec.709: written as its Rec.709 colour.
  scene.materials[0].base_color_space = ColorPickerSpace::srgb;
  const Scene back = test::write_and_reload(scene, dir / "inside.glb");
  const Vec3f gold = Vec3f(conversion("acescg", "srgb") * Vec3d(0.9, 0.6, 0.2));
  EXPECT_EQ(mesh_material(back, 1).base_color_space, ColorPickerSpace::srgb);
  expect_near(mesh_material(back, 1).base_color, gold, 1e-5f, "gold");
  // The Rec.2020 green does not: refused, naming the material.
  scene.materials[0].base_color_space = ColorPickerSpace::rec2020;
  const std::string message = test::error_of<UsageError>([&] { write_scene_glb(scene, dir / "outside.glb"); });
  EXPECT_NE(message.find("'green'"), std::string::npos) << message;
  EXPECT_NE(message.find("outside Rec.709"), std::string::npos) << message;
  // A texture tinted in a wide space: glTF multiplies in Rec.709, Prism in the material's
  // space, which agree only for a grey tint.
  TextureImage grey;
  grey.name = "grey";
  grey.width = grey.height = 1;
  grey.channels = 3;
  grey.texels = {0.5f, 0.5f, 0.5f};
  scene.textures = {grey};
  scene.materials[0].base_color_space = ColorPickerSpace::srgb;
  scene.materials[1].base_color_texture = 0;
  const std::string tinted = test::error_of<UsageError>([&] { write_scene_glb(scene, dir / "tinted.glb"); });
  EXPECT_NE(tinted.find("'gold': a texture tinted in acescg"), std::string::npos) << tinted;
}

std::string pbrt_triangle() {
  return "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n";
}

TEST(WideGamutFormats, PbrtColorSpaceIsGraphicsStateForReflectancesAndLights) {
  const std::string text = "WorldBegin\n"
                           "AttributeBegin\n"
                           "  ColorSpace \"rec2020\"\n"
                           "  Material \"diffuse\" \"rgb reflectance\" [0.05 0.6 0.05]\n" + pbrt_triangle() +
                           "  AttributeBegin\n"
                           "    AreaLightSource \"diffuse\" \"rgb L\" [0.2 0.5 1]\n" + pbrt_triangle() +
                           "  AttributeEnd\n"
                           "  ColorSpace \"aces2065-1\"\n"
                           "  Material \"conductor\" \"rgb reflectance\" [0.7 0.5 0.3]\n" + pbrt_triangle() +
                           "  ColorSpace \"dci-p3\"\n"
                           "  Texture \"tint\" \"spectrum\" \"constant\" \"rgb value\" [0.2 0.6 0.3]\n"
                           "  Material \"diffuse\" \"texture reflectance\" \"tint\"\n" + pbrt_triangle() +
                           "AttributeEnd\n"
                           "Material \"diffuse\" \"rgb reflectance\" [0.05 0.6 0.05]\n" + pbrt_triangle();
  const Scene scene = parse_pbrt_scene(text, "test.pbrt", {});
  ASSERT_EQ(scene.meshes.size(), 5u);
  // rec2020: as written.
  EXPECT_EQ(mesh_material(scene, 0).base_color_space, ColorPickerSpace::rec2020);
  EXPECT_EQ(mesh_material(scene, 0).base_color, kRec2020Green);
  const Emission& e = mesh_material(scene, 1).emission;
  EXPECT_EQ(e.color_space, ColorPickerSpace::rec2020);
  EXPECT_EQ(e.color, Vec3f(0.2f, 0.5f, 1.0f));
  // pbrt-v4 keeps an rgb light's own luminance, here Rec.2020's Y of the colour.
  EXPECT_NEAR(e.luminance_nits, relative_luminance(Vec3f(0.2f, 0.5f, 1.0f), ColorPickerSpace::rec2020), 1e-5);
  // aces2065-1: in ACEScg, the same colour.
  EXPECT_EQ(mesh_material(scene, 2).base_color_space, ColorPickerSpace::acescg);
  expect_near(mesh_material(scene, 2).base_color, Vec3f(conversion("aces2065-1", "acescg") * Vec3d(0.7, 0.5, 0.3)),
              1e-6f, "aces2065-1");
  // dci-p3 (pbrt-v4's has D65 white): in Rec.2020, a constant texture's value included.
  EXPECT_EQ(mesh_material(scene, 3).base_color_space, ColorPickerSpace::rec2020);
  expect_near(mesh_material(scene, 3).base_color, Vec3f(conversion("display-p3", "rec2020") * Vec3d(0.2, 0.6, 0.3)),
              1e-6f, "dci-p3");
  // AttributeEnd restored sRGB.
  EXPECT_EQ(mesh_material(scene, 4).base_color_space, ColorPickerSpace::srgb);
  EXPECT_EQ(mesh_material(scene, 4).base_color, kRec2020Green);
  for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("ColorSpace"), std::string::npos) << w;
}

TEST(WideGamutFormats, PbrtUnknownColorSpaceIsAnErrorAtItsLine) {
  const std::string message = test::error_of<SceneError>(
      [] { parse_pbrt_scene("WorldBegin\n\nColorSpace \"prophoto\"\n", "test.pbrt", {}); });
  EXPECT_NE(message.find("test.pbrt:3"), std::string::npos) << message;
  EXPECT_NE(message.find("'prophoto'"), std::string::npos) << message;
}

TEST(WideGamutFormats, PbrtAcesLightsAreSaidToBeWhiteBalanced) {
  const Scene scene = parse_pbrt_scene(
      "ColorSpace \"aces2065-1\"\nWorldBegin\nLightSource \"distant\" \"rgb L\" [1 1 1]\n" + pbrt_triangle(),
      "test.pbrt", {});
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].color_space, ColorPickerSpace::acescg);
  bool said = false;
  for (const std::string& w : scene.warnings) said |= w.find("pbrt-v4 emits the ACES white") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(WideGamutFormats, PrismInfoCountsWideGamutMaterials) {
  const std::string summary = format_scene_summary(wide_gamut_scene());
  EXPECT_NE(summary.find(", 2 wide-gamut"), std::string::npos) << summary;
}

TEST(WideGamutFormats, TheSpaceIsPartOfTheImageFingerprint) {
  Scene a = wide_gamut_scene();
  Scene b = a;
  b.materials[0].base_color_space = ColorPickerSpace::acescg;
  RenderSettings settings;
  EXPECT_NE(image_fingerprint(a, settings), image_fingerprint(b, settings));
}

}  // namespace
}  // namespace prism::loaders
