// Rays that leave the scene: LightSampler::escaped with a uniform environment, in a scene
// whose only other emitter is an emissive sphere of N triangles (a textured-emission model
// such as glTF's DamagedHelmet makes every triangle an emitter). escaped() visits only the
// environment and sized directional lights, so its cost must not grow with N (it did:
// a loop over every emitter, 16× slower renders of DamagedHelmet).
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/core/pcg32.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/loaders/sphere_mesh.h"
#include "prism/sampling/warps.h"

namespace {

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
  const prism::LightSampler lights(scene, prism::scene_bounds(scene));
  prism::Pcg32 rng(3, 4);
  std::vector<prism::Vec3f> directions(4096);
  for (auto& d : directions) d = prism::sample_uniform_sphere(prism::Vec2f(rng.next_float(), rng.next_float()));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(lights.escaped(directions[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
  state.counters["emissive_triangles"] = static_cast<double>(scene.meshes[0].triangle_count());
}
BENCHMARK(BM_LightEscaped)->Arg(4)->Arg(32)->Arg(128);

}  // namespace
