#include "prism/scene/loaders/atrium_generator.h"

#include <gtest/gtest.h>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"

namespace prism::loaders {
namespace {

TEST(AtriumGenerator, SizeFollowsTheTargetAndIsDeterministic) {
  for (std::size_t target : {20'000u, 100'000u, 400'000u}) {
    const Scene s = generate_atrium(target);
    EXPECT_NEAR(static_cast<double>(s.triangle_count()), static_cast<double>(target), 0.1 * target) << target;
    EXPECT_NO_THROW(validate_scene(s));
  }
  const Scene a = generate_atrium(50'000), b = generate_atrium(50'000);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
    EXPECT_TRUE(a.meshes[i].positions == b.meshes[i].positions);
  }
  EXPECT_THROW(generate_atrium(10), UsageError);
}

TEST(AtriumGenerator, HasTheSponzaLikeIngredients) {
  const SceneSummary s = summarize_scene(generate_atrium(20'000));
  EXPECT_EQ(s.materials_by_type.at("conductor"), 1u);
  EXPECT_EQ(s.materials_by_type.at("dielectric"), 1u);
  EXPECT_EQ(s.emissive_materials, 1u);
  EXPECT_EQ(s.lights_by_type.at("environment"), 1u);
}

// Written as JSON and as pbrt-v4, the atrium loads back with the same geometry.
TEST(AtriumGenerator, RoundTripsThroughJsonAndPbrt) {
  test::ScratchFolder dir;
  const Scene original = generate_atrium(20'000);
  for (const char* name : {"atrium.json", "atrium.pbrt"}) {
    const auto path = dir / name;
    if (path.extension() == ".json") write_scene_json(original, path);
    else write_scene_pbrt(original, path);
    const Scene loaded = load_scene(path.string());
    EXPECT_EQ(loaded.triangle_count(), original.triangle_count()) << name;
    const SceneSummary s = summarize_scene(loaded);
    EXPECT_EQ(s.materials_by_type.at("conductor"), 1u) << name;
    EXPECT_EQ(s.materials_by_type.at("dielectric"), 1u) << name;
    EXPECT_EQ(s.emissive_materials, 1u) << name;
    EXPECT_NEAR(length(loaded.camera.eye - original.camera.eye), 0.0f, 1e-4f) << name;
    EXPECT_NEAR(length(normalize(loaded.camera.target - loaded.camera.eye) -
                       normalize(original.camera.target - original.camera.eye)),
                0.0f, 1e-4f)
        << name;
    for (const Material& m : loaded.materials)
      if (m.is_emissive()) {
        EXPECT_NEAR(m.emission.luminance_nits, 40.0f, 1e-2f) << name;
      }
    ASSERT_EQ(loaded.lights.size(), 1u);
    EXPECT_NEAR(loaded.lights[0].intensity, original.lights[0].intensity, 1e-3f) << name;
  }
}

TEST(AtriumGenerator, RoundTripsThroughGlb) {
  test::ScratchFolder dir;
  const Scene original = generate_atrium(20'000);
  write_scene_glb(original, dir / "atrium.glb");
  const Scene loaded = load_scene((dir / "atrium.glb").string());
  EXPECT_EQ(loaded.triangle_count(), original.triangle_count());
  const SceneSummary s = summarize_scene(loaded);
  EXPECT_EQ(s.materials_by_type.at("dielectric"), 1u);
  EXPECT_EQ(s.emissive_materials, 1u);
  for (const Material& m : loaded.materials)
    if (m.is_emissive()) {
      EXPECT_NEAR(m.emission.luminance_nits, 40.0f, 1e-2f);
    }
  EXPECT_NEAR(length(loaded.camera.eye - original.camera.eye), 0.0f, 1e-4f);
  EXPECT_NEAR(length(normalize(loaded.camera.target - loaded.camera.eye) -
                     normalize(original.camera.target - original.camera.eye)),
              0.0f, 1e-4f);
  EXPECT_NEAR(loaded.camera.fov_degrees, original.camera.fov_degrees, 1e-3f);
}

}  // namespace
}  // namespace prism::loaders
