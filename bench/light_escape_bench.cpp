// Rays that leave the scene: LightSampler::escaped with a uniform environment, in a scene
// whose only other emitter is an emissive sphere of N triangles (a textured-emission model
// such as glTF's DamagedHelmet makes every triangle an emitter). escaped() visits only the
// environment and sized directional lights, so its cost must not grow with N (it did:
// a loop over every emitter, 16× slower renders of DamagedHelmet). And with a textured sky.
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

// The same with a textured (equirectangular, float RGB) sky of the given width: what every
// escaped ray pays for the map's pdf and radiance at its direction.
void BM_LightEscapedTexturedSky(benchmark::State& state) {
  prism::Scene scene;
  prism::TextureImage sky_texels;
  sky_texels.width = static_cast<int>(state.range(0));
  sky_texels.height = sky_texels.width / 2;
  sky_texels.channels = 3;
  prism::Pcg32 texel_rng(5, 6);
  sky_texels.texels.resize(static_cast<std::size_t>(sky_texels.width) * sky_texels.height * 3);
  for (float& v : sky_texels.texels) v = 0.2f + texel_rng.next_float();
  scene.textures.push_back(std::move(sky_texels));
  prism::Light sky;
  sky.type = prism::LightType::environment;
  sky.environment_texture = 0;
  scene.lights.push_back(sky);
  run_escapes(state, scene);
}
BENCHMARK(BM_LightEscapedTexturedSky)->Arg(1024);

}  // namespace
