// metallic_roughness' specular layer (KHR_materials_specular) and IOR (KHR_materials_ior)
// end to end: a black dielectric floor under a white sky shows exactly its layer's albedo,
// the JSON keys and their rules, the writers, and the image fingerprint.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "scene/loaders/loader_test_files.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"
#include "support/floor_under_sky.h"
#include "support/write_and_reload.h"

namespace prism {
namespace {

using test::floor_under_white_sky;

// A black, nearly smooth dielectric (roughness 0.1: α = 0.01) seen at normal incidence
// reflects s F0 of the sky, F0 = ((η − 1)/(η + 1))² × the colour's mean: with η = 2, colour
// 0.9 and s = 0.5, 0.05. The bound: 5σ of the film's noise, plus 2e-3 for the lobe's
// shadowing and Schlick's growth over its width (tests/bsdf/specular_layer_test.cpp).
TEST(SpecularLayerRender, BlackDielectricShowsItsWeightedF0) {
  const Scene scene = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "base_color": [0, 0, 0],
      "roughness": 0.1, "ior": 2, "specular": 0.5, "specular_color": [0.9, 0.9, 0.9]})");
  const double expected = 0.5 * 0.9 / 9.0;
  for (TransportKind kind : {TransportKind::rgb, TransportKind::spectral}) {
    const test::BlockEstimate e = test::block_estimate(
        render(scene, test::direct_light_settings(kind, LightEstimator::mis, 64, 5)).film, 0, 0, 8, 8);
    EXPECT_NEAR(e.mean.y, expected, 5.0 * std::sqrt(e.variance.y) + 2e-3) << static_cast<int>(kind);
  }
}

// A tinted specular colour reflects per channel: with colour (0.2, 1, 0.4) and η = 2 the
// same floor reflects F0 = (0.2, 1, 0.4)/9, i.e. what a Lambertian floor of that colour
// reflects under the sky, channel by channel of the film, in both transports (spectral:
// the F0 colour is upsampled as the base colour is). Its mean grey would give 0.0593 in
// every channel. The bound: 5σ of both films' noise plus, as above, 2e-3 for the lobe.
TEST(SpecularLayerRender, TintedSpecularColourReflectsPerChannel) {
  const Scene tinted = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "base_color": [0, 0, 0],
      "roughness": 0.1, "ior": 2, "specular_color": [0.2, 1, 0.4]})");
  const Scene lambert = floor_under_white_sky(R"({"name": "floor", "type": "diffuse",
      "base_color": [0.022222222, 0.111111111, 0.044444444]})");
  for (TransportKind kind : {TransportKind::rgb, TransportKind::spectral}) {
    const auto settings = test::direct_light_settings(kind, LightEstimator::mis, 64, 5);
    const test::BlockEstimate t = test::block_estimate(render(tinted, settings).film, 0, 0, 8, 8);
    const test::BlockEstimate l = test::block_estimate(render(lambert, settings).film, 0, 0, 8, 8);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(t.mean[c], l.mean[c], 5.0 * std::sqrt(t.variance[c] + l.variance[c]) + 2e-3)
          << static_cast<int>(kind) << " channel " << c;
    if (kind == TransportKind::rgb) {
      EXPECT_NEAR(l.mean.y, 1.0 / 9.0, 1e-4);  // the working space's G
    }
  }
}

TEST(SpecularLayerRender, JsonKeysAreForMetallicRoughnessOnly) {
  const auto error = [](const std::string& material) {
    return test::error_of<SceneError>([&] { floor_under_white_sky(material); });
  };
  EXPECT_NE(error(R"({"name": "floor", "type": "diffuse", "specular": 0.5})")
                .find("materials[0].specular: only metallic_roughness materials"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "metallic_roughness", "specular": 1.5})").find("materials[0].specular"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "metallic_roughness", "specular_color": [1, -1, 1]})")
                .find("materials[0].specular_color: colour components must not be negative"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "floor", "type": "dielectric", "specular_texture": "s.png"})")
                .find("materials[0].specular_texture: only metallic_roughness materials"),
            std::string::npos);
}

// A 2×1 texture of RGBA texels.
TextureImage rgba_texture(const char* name, std::initializer_list<float> texels) {
  TextureImage t;
  t.name = name;
  t.width = 2;
  t.height = 1;
  t.channels = 4;
  t.texels = texels;
  return t;
}

TEST(SpecularLayerRender, JsonAndGlbKeepTheLayerAndTheIor) {
  Scene original = floor_under_white_sky(R"({"name": "floor", "type": "metallic_roughness", "base_color": [0.2, 0.3, 0.4],
      "ior": 1.7, "specular": 0.3, "specular_color": [0.5, 0.6, 0.7]})");
  original.meshes[0].uvs = {Vec2f(0, 0), Vec2f(1, 0), Vec2f(1, 1), Vec2f(0, 1)};
  original.textures.push_back(rgba_texture("weight", {0, 0, 0, 0.5f, 0, 0, 0, 1}));
  original.textures.push_back(rgba_texture("tint", {1, 0.5f, 0.25f, 1, 0.25f, 0.5f, 1, 1}));
  original.textures[1].encoding = TextureEncoding::srgb;
  original.materials[0].specular_texture = 0;
  original.materials[0].specular_color_texture = 1;
  test::ScratchFolder dir;
  for (const char* name : {"floor.json", "floor.glb"}) {
    const std::filesystem::path path = dir / name;
    const Scene loaded = test::write_and_reload(original, path);
    const Material& m = loaded.materials[loaded.meshes[0].material];
    EXPECT_EQ(m.type, MaterialType::metallic_roughness) << name;
    EXPECT_FLOAT_EQ(m.ior, 1.7f) << name;
    EXPECT_FLOAT_EQ(m.specular, 0.3f) << name;
    EXPECT_EQ(m.specular_color, Vec3f(0.5f, 0.6f, 0.7f)) << name;
    ASSERT_GE(m.specular_texture, 0) << name;
    ASSERT_GE(m.specular_color_texture, 0) << name;
    EXPECT_EQ(loaded.textures[m.specular_texture].encoding, TextureEncoding::linear) << name;
    EXPECT_EQ(loaded.textures[m.specular_color_texture].encoding, TextureEncoding::srgb) << name;
    const TextureImage& weight = loaded.textures[m.specular_texture];
    ASSERT_GE(weight.channels, 2) << name;
    EXPECT_NEAR(weight.value(weight.channels - 1), 0.5f, 1.0f / 255) << name;  // A, through an 8-bit PNG
  }
}

TEST(SpecularLayerRender, TheLayerIsPartOfTheImageFingerprint) {
  RenderSettings s;
  s.width = s.height = 4;
  const std::string plain = R"({"name": "floor", "type": "metallic_roughness"})";
  const std::uint64_t before = image_fingerprint(floor_under_white_sky(plain), s);
  Scene a = floor_under_white_sky(plain);
  a.materials[0].specular = 0.5f;
  EXPECT_NE(image_fingerprint(a, s), before);
  Scene b = floor_under_white_sky(plain);
  b.materials[0].specular_color = Vec3f(0.5f);
  EXPECT_NE(image_fingerprint(b, s), before);
  Scene c = floor_under_white_sky(plain);
  c.textures.push_back(rgba_texture("weight", {0, 0, 0, 0.5f, 0, 0, 0, 1}));
  const std::uint64_t untextured = image_fingerprint(c, s);
  c.materials[0].specular_texture = 0;
  EXPECT_NE(image_fingerprint(c, s), untextured);
}

}  // namespace
}  // namespace prism
