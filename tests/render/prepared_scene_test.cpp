// Handing a scene over to the renderer (PreparedScene(Scene&&), render(Scene&&)) moves its
// meshes and texels instead of copying them, and renders exactly what a copy renders.
#include <gtest/gtest.h>
#include <time.h>

#include "prism/render/prepared_scene.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"

namespace prism {
namespace {

// The Cornell box with a 64×64 RGB texture on its first material, so that both the
// geometry and the texels are big enough to be heap buffers worth tracking.
Scene textured_cornell_box() {
  Scene scene = make_cornell_box();
  TextureImage t;
  t.name = "checker";
  t.width = t.height = 64;
  t.channels = 3;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const float v = ((x / 8 + y / 8) % 2) != 0 ? 0.8f : 0.2f;
      t.texels.insert(t.texels.end(), {v, 0.5f * v, 0.25f + 0.5f * v});
    }
  scene.textures.push_back(std::move(t));
  scene.materials[0].base_color_texture = 0;
  for (TriangleMesh& m : scene.meshes)
    if (m.uvs.empty()) m.uvs.assign(m.positions.size(), Vec2f(0.3f, 0.6f));
  return scene;
}

TEST(PreparedScene, TakingTheSceneOverMovesItsBuffers) {
  Scene scene = textured_cornell_box();
  const float* texels = scene.textures[0].texels.data();
  const Vec3f* positions = scene.meshes[0].positions.data();
  const PreparedScene prepared(std::move(scene));
  EXPECT_EQ(prepared.scene().textures[0].texels.data(), texels);
  EXPECT_EQ(prepared.scene().meshes[0].positions.data(), positions);
}

// The textures' mip pyramids are built once per prepared scene (not per render, so a
// viewer restart does not rebuild them), level 0 being the prepared scene's own texels.
TEST(PreparedScene, BuildsOneMipPyramidPerTextureOnce) {
  const PreparedScene prepared(textured_cornell_box());
  ASSERT_EQ(prepared.mip_pyramids().size(), 1u);
  const MipPyramid& p = prepared.mip_pyramids()[0];
  ASSERT_EQ(p.levels.size(), 7u);  // 64² … 1²
  EXPECT_EQ(p.levels[0].data(), prepared.scene().textures[0].texels.data());
  EXPECT_EQ(p.levels[6].width, 1);
  // The 1×1 level is the checker's mean: half 0.8 and half 0.2 in the first channel.
  EXPECT_NEAR(p.levels[6].texels[0], 0.5f, 1e-6f);
}

// Textures no material uses (environment maps, read texel by texel) keep level 0 alone;
// when a material takes one up, its pyramid is built then.
TEST(PreparedScene, TexturesNoMaterialUsesHaveNoMipLevels) {
  Scene scene = textured_cornell_box();
  scene.materials[0].base_color_texture = -1;
  Light sky;
  sky.type = LightType::environment;
  sky.environment_texture = 0;
  scene.lights.push_back(sky);
  PreparedScene prepared(scene);
  ASSERT_EQ(prepared.mip_pyramids().size(), 1u);
  ASSERT_EQ(prepared.mip_pyramids()[0].levels.size(), 1u);
  EXPECT_EQ(prepared.mip_pyramids()[0].levels[0].data(), prepared.scene().textures[0].texels.data());
  std::vector<Material> materials = prepared.scene().materials;
  materials[0].base_color_texture = 0;
  prepared.set_materials(materials);
  ASSERT_EQ(prepared.mip_pyramids()[0].levels.size(), 7u);
  EXPECT_NEAR(prepared.mip_pyramids()[0].levels[6].texels[0], 0.5f, 1e-6f);
}

TEST(PreparedScene, CopyingTheSceneLeavesItIntact) {
  const Scene scene = textured_cornell_box();
  const PreparedScene prepared(scene);
  EXPECT_NE(prepared.scene().textures[0].texels.data(), scene.textures[0].texels.data());
  EXPECT_EQ(prepared.scene().textures[0].texels, scene.textures[0].texels);
  EXPECT_EQ(prepared.scene().meshes.size(), scene.meshes.size());
}

TEST(PreparedScene, FlatteningInstancesStillMovesTheTexels) {
  Scene scene = textured_cornell_box();
  // Every mesh drawn twice: once in place, once shifted along x.
  const std::size_t meshes = scene.meshes.size();
  for (std::uint32_t i = 0; i < meshes; ++i) {
    scene.instances.push_back(Instance{i, Transform{}});
    scene.instances.push_back(Instance{i, Transform::translate(Vec3f(1000.0f, 0.0f, 0.0f))});
  }
  const float* texels = scene.textures[0].texels.data();
  const PreparedScene prepared(std::move(scene));
  EXPECT_EQ(prepared.scene().textures[0].texels.data(), texels);
  EXPECT_EQ(prepared.scene().meshes.size(), 2 * meshes);
  EXPECT_TRUE(prepared.scene().instances.empty());
}

// The light sampler is kept across renders (a viewer restart after a camera move) and
// rebuilt only when what it is built from changes: the options, a material's emission, a
// light.
TEST(PreparedScene, KeepsTheLightSamplerUntilTheEmittersChange) {
  PreparedScene prepared(textured_cornell_box());
  const LightSamplerOptions options;
  const auto first = prepared.light_sampler(options);
  EXPECT_EQ(prepared.light_sampler(options), first);
  Camera camera = prepared.scene().camera;
  camera.eye.x += 1.0f;
  prepared.set_camera(camera);
  EXPECT_EQ(prepared.light_sampler(options), first);
  std::vector<Material> materials = prepared.scene().materials;
  materials[0].base_color = Vec3f(0.1f);  // not an emitter's business
  prepared.set_materials(materials);
  EXPECT_EQ(prepared.light_sampler(options), first);
  prepared.set_lights(prepared.scene().lights);  // the same lights again
  EXPECT_EQ(prepared.light_sampler(options), first);

  std::size_t light_material = materials.size();
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].is_emissive()) light_material = i;
  ASSERT_LT(light_material, materials.size());
  materials[light_material].emission.luminance_nits *= 2.0f;
  prepared.set_materials(materials);
  const auto brighter = prepared.light_sampler(options);
  EXPECT_NE(brighter, first);
  EXPECT_EQ(first->light_count(), brighter->light_count());  // the old one is still usable

  Light sun;
  sun.type = LightType::directional;
  sun.intensity = 3.0f;
  prepared.set_lights({sun});
  const auto with_sun = prepared.light_sampler(options);
  EXPECT_NE(with_sun, brighter);
  EXPECT_EQ(with_sun->light_count(), brighter->light_count() + 1);

  LightSamplerOptions other = options;
  other.reuse_selection_sample = !other.reuse_selection_sample;
  EXPECT_NE(prepared.light_sampler(other), with_sun);
}

TEST(PreparedScene, RenderingAHandedOverSceneGivesTheSameImage) {
  RenderSettings settings;
  settings.width = settings.height = 24;
  settings.samples_per_pixel = 2;
  settings.threads = 1;
  const Scene scene = textured_cornell_box();
  const RenderResult copied = render(scene, settings, RenderHooks{});
  const RenderResult moved = render(textured_cornell_box(), settings, RenderHooks{});
  EXPECT_EQ(copied.film.sums(), moved.film.sums());  // bit for bit: the same numbers either way
  EXPECT_EQ(copied.film.counts(), moved.film.counts());
}

double cpu_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// --threads 1 holds for the preparation as well as for the passes: the BVH build (Embree
// on oneTBB), the mip pyramids and the light sampler run on the calling thread alone. A
// 320 000-triangle grid beside the box makes the build the bulk of the call (tens of ms on
// one core), so on a multi-core machine an unlimited build hands half of it or more to
// TBB's workers. What other threads spend is the process's CPU time less this thread's.
TEST(PreparedScene, TheThreadLimitHoldsWhilePreparing) {
  Scene scene = make_cornell_box();
  TriangleMesh grid;
  grid.name = "grid";
  constexpr std::uint32_t kQuads = 400;  // per side: 2 · 400² triangles
  for (std::uint32_t y = 0; y <= kQuads; ++y)
    for (std::uint32_t x = 0; x <= kQuads; ++x)
      grid.positions.push_back(Vec3f(5000.0f + float(x), float(y), 0.1f * float((x * 7 + y * 13) % 5)));
  for (std::uint32_t y = 0; y < kQuads; ++y)
    for (std::uint32_t x = 0; x < kQuads; ++x) {
      const std::uint32_t v = y * (kQuads + 1) + x;
      grid.indices.insert(grid.indices.end(), {v, v + 1, v + kQuads + 2, v, v + kQuads + 2, v + kQuads + 1});
    }
  scene.meshes.push_back(std::move(grid));
  RenderSettings settings;
  settings.width = settings.height = 4;
  settings.samples_per_pixel = 1;
  settings.threads = 1;
  const double process_before = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
  const double thread_before = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
  render(std::move(scene), settings, RenderHooks{});
  const double thread_seconds = cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - thread_before;
  const double other_seconds = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - process_before - thread_seconds;
  // Limited, the workers stay asleep: what they may still spend is the tail of a spin-wait
  // left from an earlier parallel loop in this process (≪ 5 ms) and clock granularity.
  // Unlimited, they take a large share of the build (measured on 2 cores: 86–90 % of this thread's
  // time); 10 % of this thread's time + 5 ms lies well between the two.
  EXPECT_LT(other_seconds, 0.1 * thread_seconds + 0.005)
      << "other threads " << other_seconds << " s, this thread " << thread_seconds << " s";
}

}  // namespace
}  // namespace prism
