// Tinted glass in a render: a thin pane (JSON "thin_walled") in front of a uniform white
// sky, seen at normal incidence, shows R' + (1 − R') · tint per channel (the sky behind the
// camera reflected, the sky beyond transmitted through the tint). And the JSON rules:
// glass without a base_color is clear; glTF's transmission turns metallic_roughness into
// tinted glass; a distribution other than GGX or transmission where nothing transmits is
// an error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/loaders/json_scene.h"
#include "scene/loaders/loader_test_files.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

Scene pane_scene(const std::string& material) {
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [)" + material + R"(],
    "meshes": [{"name": "pane", "material": "glass",
                "positions": [[-10, -10, 0], [10, -10, 0], [10, 10, 0], [-10, 10, 0]],
                "indices": [0, 1, 2, 0, 2, 3]}],
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_degrees": 2},
    "environment": {"color": [1, 1, 1], "luminance_nits": 1}})",
                                   "pane.json", {}, "pane");
}

// Each sample either reflects (the sky, 1) or passes the pane (the tint): the film's own
// noise is part of every tolerance below (5σ), beside 1e-4.
test::BlockEstimate render_mean(const Scene& scene) {
  RenderSettings s;
  s.width = s.height = 4;
  s.samples_per_pixel = 64;
  s.transport.kind = TransportKind::rgb;
  s.path.max_depth = 4;
  const Film film = render(scene, s).film;
  return test::block_estimate(film, 0, 0, film.width(), film.height());
}

TEST(GlassTintRender, ThinPaneTransmitsThroughItsTint) {
  // η = 1.5 at normal incidence: R = 0.04, R' = 2R/(1 + R). Within 1° of normal incidence
  // R' changes by < 1e-5; 1e-4 covers that and float accumulation.
  const double r = 0.08 / 1.04;
  const Vec3d tint(1.0, 0.5, 0.25);
  const test::BlockEstimate e = render_mean(pane_scene(
      R"({"name": "glass", "type": "dielectric", "thin_walled": true, "base_color": [1, 0.5, 0.25]})"));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.mean[c], r + (1.0 - r) * tint[c], 5.0 * std::sqrt(e.variance[c]) + 1e-4) << "channel " << c;
  EXPECT_LT(e.mean[2], 0.5);  // clearly tinted, not the clear pane's 1
  // Glass given no colour is clear: the sky's 1 in every channel, every sample.
  const test::BlockEstimate clear =
      render_mean(pane_scene(R"({"name": "glass", "type": "dielectric", "thin_walled": true})"));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(clear.mean[c], 1.0, 1e-4) << "channel " << c;
}

TEST(GlassTintRender, TransmittingMetallicRoughnessIsTintedGlass) {
  const Scene scene = pane_scene(R"({"name": "glass", "type": "metallic_roughness", "metallic": 0,
      "roughness": 0, "transmission": 1, "thin_walled": true, "base_color": [0.25, 1, 0.5]})");
  EXPECT_EQ(scene.materials[0].type, MaterialType::dielectric);
  const double r = 0.08 / 1.04;
  const test::BlockEstimate e = render_mean(scene);
  const Vec3d tint(0.25, 1.0, 0.5);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.mean[c], r + (1.0 - r) * tint[c], 5.0 * std::sqrt(e.variance[c]) + 1e-4) << "channel " << c;
  EXPECT_TRUE(scene.warnings.empty());
  const Scene partial = pane_scene(R"({"name": "glass", "type": "metallic_roughness", "transmission": 0.5})");
  ASSERT_EQ(partial.warnings.size(), 1u);
  EXPECT_NE(partial.warnings[0].find("materials[0].transmission: partial transmission"), std::string::npos)
      << partial.warnings[0];
}

TEST(GlassTintRender, KeysWithoutEffectAreErrors) {
  const std::string microfacet = test::error_of<SceneError>(
      [] { pane_scene(R"({"name": "glass", "type": "metallic_roughness", "microfacet": "beckmann"})"); });
  EXPECT_NE(microfacet.find("materials[0].microfacet: only conductor and dielectric"), std::string::npos)
      << microfacet;
  EXPECT_NO_THROW(pane_scene(R"({"name": "glass", "type": "metallic_roughness", "microfacet": "ggx"})"));
  EXPECT_NO_THROW(pane_scene(R"({"name": "glass", "type": "conductor", "microfacet": "beckmann"})"));
  const std::string transmission = test::error_of<SceneError>(
      [] { pane_scene(R"({"name": "glass", "type": "diffuse", "transmission": 1})"); });
  EXPECT_NE(transmission.find("materials[0].transmission: only metallic_roughness"), std::string::npos)
      << transmission;
}

}  // namespace
}  // namespace prism
