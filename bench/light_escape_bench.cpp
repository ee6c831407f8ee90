// Rays that leave the scene: LightSampler::escaped with a uniform environment, in a scene
// whose only other emitter is an emissive sphere of N triangles (a textured-emission model
// such as glTF's DamagedHelmet makes every triangle an emitter). escaped() visits only the
// environment and sized directional lights, so its cost must not grow with N (it did:
// a loop over every emitter, 16× slower renders of DamagedHelmet). And with a textured sky,
// whose light samples are measured here too.
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/core/pcg32.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/loaders/sphere_mesh.h"
#include "prism/sampling/warps.h"

namespace {

// Rays leaving the scene in 4096 uniform directions, taken in turn.
void run_escapes(benchmark::State& state, const prism::Scene& scene) {
  const prism::LightSampler lights(scene, prism::scene_bounds(scene));
  prism::Pcg32 rng(3, 4);
  std::vector<prism::Vec3f> directions(4096);
  for (auto& d : directions) d = prism::sample_uniform_sphere(prism::Vec2f(rng.next_float(), rng.next_float()));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(lights.escaped(directions[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}

void BM_LightEscaped(benchmark::State& state) {
  prism::Scene scene;
  const int rings = static_cast<int>(state.range(0));
  scene.meshes.push_back(prism::loaders::make_uv_sphere(prism::Vec3f(0.0f), 1.0f, rings));
  prism::Material lamp;
  lamp.emission.color = prism::Vec3f(1.0f);
  lamp.emission.luminance_nits = 10.0f;
  scene.materials.push_back(lamp);
  prism::Light sky;
  sky.type = prism::LightType::environment;
  scene.lights.push_back(sky);
  run_escapes(state, scene);
  state.counters["emissive_triangles"] = static_cast<double>(scene.meshes[0].triangle_count());
}
BENCHMARK(BM_LightEscaped)->Arg(4)->Arg(32)->Arg(128);

// A scene lit only by a textured (equirectangular, float RGB) sky `width` texels wide.
prism::Scene textured_sky_scene(int width) {
  prism::Scene scene;
  prism::TextureImage sky_texels;
  sky_texels.width = width;
  sky_texels.height = width / 2;
  sky_texels.channels = 3;
  prism::Pcg32 texel_rng(5, 6);
  sky_texels.texels.resize(static_cast<std::size_t>(sky_texels.width) * sky_texels.height * 3);
  for (float& v : sky_texels.texels) v = 0.2f + texel_rng.next_float();
  scene.textures.push_back(std::move(sky_texels));
  prism::Light sky;
  sky.type = prism::LightType::environment;
  sky.environment_texture = 0;
  scene.lights.push_back(sky);
  return scene;
}

// The same with a textured sky: what every escaped ray pays for the map's pdf and radiance
// at its direction.
void BM_LightEscapedTexturedSky(benchmark::State& state) {
  run_escapes(state, textured_sky_scene(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_LightEscapedTexturedSky)->Arg(1024);

// Light samples of the textured sky (next-event estimation's side): a direction from the
// map's distribution, its pdf and its radiance, for 4096 stratified numbers taken in turn.
void BM_LightSampleTexturedSky(benchmark::State& state) {
  const prism::Scene scene = textured_sky_scene(static_cast<int>(state.range(0)));
  const prism::LightSampler lights(scene, prism::scene_bounds(scene));
  prism::Pcg32 rng(7, 8);
  std::vector<prism::Vec2f> numbers(4096);
  for (auto& u : numbers) u = prism::Vec2f(rng.next_float(), rng.next_float());
  const prism::Vec3f reference(0.0f), normal(0.0f, 0.0f, 1.0f);
  std::size_t i = 0;
  for (auto _ : state) {
    const prism::Vec2f u = numbers[i++ & 4095];
    benchmark::DoNotOptimize(lights.sample(reference, u.x, u, normal));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightSampleTexturedSky)->Arg(1024)->Arg(4096);

}  // namespace
