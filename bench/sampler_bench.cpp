// The per-path random numbers (sampling/pixel_sampler.h), which the integrator asks for once
// per camera ray and once per bounce. Issue 8's profile had the padded Sobol' sampler at
// about a sixth of a single-threaded Cornell-box render. Baselines in the same binary:
//   BM_Sobol2DDefinition: the 2D request written as its definition (seven bit reversals),
//                         against BM_Sobol2D, the sampler's form (three);
//   BM_BounceSamples/31:  the whole 7-number block, against /21, what a diffuse vertex
//                         before Russian roulette reads (light and direction only).
#include <benchmark/benchmark.h>

#include "prism/core/sample_stream.h"
#include "prism/sampling/owen_scrambling.h"
#include "prism/sampling/pixel_sampler.h"
#include "prism/sampling/sobol.h"

namespace {

prism::PixelSample next_sample(std::uint32_t& i) {
  ++i;
  return prism::PixelSample{1, i & 0xffffu, 256, i >> 16};
}

void BM_Sobol2DDefinition(benchmark::State& state) {
  std::uint32_t i = 0;
  for (auto _ : state) {
    const prism::PixelSample s = next_sample(i);
    const std::uint64_t pixel_key = prism::mix64(prism::mix64(s.seed ^ 0x736f626f6c5eedull) + s.pixel_index);
    const std::uint64_t h = prism::mix64(pixel_key + 0x9e3779b97f4a7c15ull * 10ull);
    const std::uint32_t index = prism::nested_uniform_scramble(s.sample_index, static_cast<std::uint32_t>(h));
    const std::uint32_t x =
        prism::nested_uniform_scramble(prism::sobol_sample_bits(index, 0), static_cast<std::uint32_t>(h >> 32));
    const std::uint32_t y = prism::nested_uniform_scramble(prism::sobol_sample_bits(index, 1),
                                                           static_cast<std::uint32_t>(prism::mix64(h) >> 32));
    benchmark::DoNotOptimize(prism::Vec2f(prism::bits_to_unit_float(x), prism::bits_to_unit_float(y)));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Sobol2DDefinition);

void BM_Sobol2D(benchmark::State& state) {
  std::uint32_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(prism::sample_2d(prism::SamplerKind::sobol, next_sample(i), 9));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Sobol2D);

void BM_BounceSamples(benchmark::State& state) {
  const auto needs = static_cast<unsigned>(state.range(0));
  std::uint32_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(prism::bounce_samples(prism::SamplerKind::sobol, next_sample(i), 2, needs));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BounceSamples)->Arg(prism::kNeedAllBounceSamples)->Arg(prism::kNeedLight | prism::kNeedDirection);

void BM_CameraSamples(benchmark::State& state) {
  std::uint32_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(prism::camera_samples(prism::SamplerKind::sobol, next_sample(i)));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CameraSamples);

}  // namespace
