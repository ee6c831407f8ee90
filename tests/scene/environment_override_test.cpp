// `--environment` (scene/environment_override.h): replaces the scene's environment, keeps
// other lights, orients the map as documented, lights a convex diffuse object exactly as a
// furnace predicts, and leaves the scene untouched when the image cannot be read.
#include "prism/scene/environment_override.h"

#include <gtest/gtest.h>

#include <cmath>

#include "loaders/loader_test_files.h"
#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/loaders/sphere_mesh.h"
#include "support/exr_rec709.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using test::kRec709;  // support/exr_rec709.h

// A unit sphere of flat facets (a convex polyhedron: every point sees only the sky) with a
// grey Lambertian material, and a camera on −z looking at it.
Scene grey_sphere_scene(float albedo) {
  Scene scene;
  scene.name = "grey-sphere";
  TriangleMesh sphere = loaders::make_uv_sphere(Vec3f(0.0f), 1.0f, 24);
  sphere.normals.clear();
  sphere.material = 0;
  scene.meshes.push_back(std::move(sphere));
  Material grey;
  grey.base_color = Vec3f(albedo);
  scene.materials.push_back(grey);
  scene.camera.eye = Vec3f(0.0f, 0.0f, -4.0f);
  scene.camera.target = Vec3f(0.0f);
  scene.camera.fov_degrees = 40.0f;
  return scene;
}

int environment_count(const Scene& scene) {
  int n = 0;
  for (const Light& l : scene.lights) n += l.type == LightType::environment ? 1 : 0;
  return n;
}

TEST(EnvironmentOverride, ReplacesTheEnvironmentAndKeepsOtherLights) {
  Scene scene = grey_sphere_scene(0.5f);
  EXPECT_FALSE(scene_has_emitters(scene));
  Light sun;
  sun.type = LightType::directional;
  scene.lights.push_back(sun);
  Light old_sky;
  old_sky.type = LightType::environment;
  old_sky.intensity = 7.0f;
  scene.lights.push_back(old_sky);
  apply_environment_override(scene, EnvironmentOverride{"uniform", 3.0f, 0.0f});
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::directional);
  EXPECT_EQ(environment_count(scene), 1);
  EXPECT_EQ(scene.lights[1].intensity, 3.0f);
  EXPECT_EQ(scene.lights[1].environment_texture, -1);
  EXPECT_TRUE(scene_has_emitters(scene));
  // No source: nothing changes.
  apply_environment_override(scene, EnvironmentOverride{});
  EXPECT_EQ(scene.lights[1].intensity, 3.0f);
  // The Cornell box emits through its light's material.
  EXPECT_TRUE(scene_has_emitters(make_cornell_box()));
}

TEST(EnvironmentOverride, BadInputIsAnErrorAndLeavesTheSceneAsItWas) {
  Scene scene = grey_sphere_scene(0.5f);
  EXPECT_THROW(apply_environment_override(scene, EnvironmentOverride{"uniform", -1.0f, 0.0f}), UsageError);
  EXPECT_THROW(apply_environment_override(scene, EnvironmentOverride{"uniform", NAN, 0.0f}), UsageError);
  EXPECT_THROW(apply_environment_override(scene, EnvironmentOverride{"uniform", 1.0f, INFINITY}), UsageError);
  const std::string message = test::error_of<IoError>(
      [&] { apply_environment_override(scene, EnvironmentOverride{"/nonexistent/sky.hdr", 1.0f, 0.0f}); });
  EXPECT_NE(message.find("sky.hdr"), std::string::npos) << message;
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(scene.textures.empty());
}

TEST(EnvironmentOverride, RotationTurnsTheMapAboutPlusY) {
  // An 8×4 linear map, bright (10) only around the map's +x direction (u = 0.5 ± 1/8,
  // v = 0.5 ± 1/4 in the equirectangular convention of light_sampler.cpp), 1 elsewhere.
  test::ScratchFolder dir;
  ImageRgbF map{8, 4, std::vector<float>(8 * 4 * 3, 1.0f)};
  for (int y = 1; y <= 2; ++y)
    for (int x = 3; x <= 4; ++x)
      for (int c = 0; c < 3; ++c) map.rgb[static_cast<std::size_t>((y * 8 + x) * 3 + c)] = 10.0f;
  write_exr(dir / "sky.exr", map, kRec709);
  for (const float degrees : {0.0f, 90.0f, -90.0f, 180.0f}) {
    Scene scene = grey_sphere_scene(0.5f);
    apply_environment_override(scene, EnvironmentOverride{(dir / "sky.exr").string(), 2.0f, degrees});
    ASSERT_EQ(scene.textures.size(), 1u);
    const LightSampler lights(scene, scene_bounds(scene));
    // +θ about +y carries the map's +x to (cos θ, 0, −sin θ).
    const float theta = degrees * 3.14159265f / 180.0f;
    const Vec3f bright(std::cos(theta), 0.0f, -std::sin(theta));
    const auto seen = lights.escaped(bright);
    ASSERT_EQ(seen.size(), 1u);
    ASSERT_TRUE(seen[0].has_rgb);
    EXPECT_FLOAT_EQ(seen[0].rgb.x, 20.0f) << degrees;  // texel 10 × 2 nits
    const auto opposite = lights.escaped(-bright);
    EXPECT_FLOAT_EQ(opposite[0].rgb.x, 2.0f) << degrees;
  }
}

TEST(EnvironmentOverride, UniformSkyLightsAConvexDiffuseObjectAsAFurnacePredicts) {
  // A convex Lambertian surface of albedo ρ under a uniform sky of radiance L reflects
  // exactly ρ·L in every direction; pixels that miss see L itself.
  Scene scene = grey_sphere_scene(0.5f);
  apply_environment_override(scene, EnvironmentOverride{"uniform", 2.0f, 0.0f});
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.samples_per_pixel = 64;
  settings.transport.kind = TransportKind::rgb;
  const RenderResult result = render(scene, settings);
  const test::BlockEstimate centre = test::block_estimate(result.film, 12, 12, 20, 20);
  for (int c = 0; c < 3; ++c) {
    // Five standard errors of the block mean (from the film's own per-pixel variance),
    // plus float accumulation rounding.
    EXPECT_NEAR(centre.mean[c], 1.0, 5.0 * std::sqrt(centre.variance[c]) + 1e-4) << c;
  }
  const test::BlockEstimate corner = test::block_estimate(result.film, 0, 0, 2, 2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(corner.mean[c], 2.0, 1e-5) << c;
}

}  // namespace
}  // namespace prism
