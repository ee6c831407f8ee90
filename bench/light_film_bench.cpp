// Next-event light sampling in the Cornell box (choose an emitter, a point on it) and
// film accumulation (one sample added to a pixel of a 512² film, random pixels).
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/core/pcg32.h"
#include "prism/render/film.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"

namespace {

void BM_LightSample(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::LightSampler lights(scene, prism::scene_bounds(scene));
  prism::Pcg32 rng(7, 8);
  std::vector<prism::Vec3f> points(4096);
  for (auto& p : points) p = prism::Vec3f(550.0f * rng.next_float(), 500.0f * rng.next_float(), 550.0f * rng.next_float());
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        lights.sample(points[i++ & 4095], rng.next_float(), prism::Vec2f(rng.next_float(), rng.next_float())));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightSample);

void BM_FilmAddSample(benchmark::State& state) {
  prism::Film film(512, 512);
  prism::Pcg32 rng(9, 10);
  std::vector<std::size_t> pixels(1 << 16);
  for (auto& p : pixels) p = rng.next_u32() % film.pixel_count();
  std::size_t i = 0;
  const prism::Vec3d v{0.5, 0.4, 0.3};
  for (auto _ : state) film.add_sample(pixels[i++ & 0xffff], v);
  benchmark::DoNotOptimize(film.sums().data());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FilmAddSample);

}  // namespace
