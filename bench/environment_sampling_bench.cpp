// Importance sampling of an environment map's texels (PiecewiseConstant2D, the marginal row
// then the column in that row's CDF) for maps of 1k, 2k and 4k width: at 4k the rows' CDFs
// are 32 MiB, so each sample's search runs through memory the caches do not hold.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "prism/core/pcg32.h"
#include "prism/sampling/piecewise_constant.h"

namespace {

// A sky-like weight: a bright sun, a smooth sky gradient and texel noise, weighted by
// sin θ as the light sampler weights equirectangular rows.
prism::PiecewiseConstant2D sky_distribution(int width) {
  const int height = width / 2;
  prism::Pcg32 rng(3, 4);
  return prism::PiecewiseConstant2D(width, height, [&](int y, std::span<float> row) {
    const float theta = std::numbers::pi_v<float> * (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
    for (int x = 0; x < width; ++x) {
      const float phi = 2.0f * std::numbers::pi_v<float> * (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
      const float sun = std::exp(-40.0f * ((theta - 0.6f) * (theta - 0.6f) + (phi - 2.0f) * (phi - 2.0f)));
      const float sky = theta < 1.6f ? 1.0f + std::cos(theta) : 0.2f;
      row[static_cast<std::size_t>(x)] = (5000.0f * sun + sky * (0.5f + rng.next_float())) * std::sin(theta);
    }
  });
}

void BM_EnvironmentSample(benchmark::State& state) {
  const prism::PiecewiseConstant2D d = sky_distribution(static_cast<int>(state.range(0)));
  prism::Pcg32 rng(5, 6);
  for (auto _ : state)
    benchmark::DoNotOptimize(d.sample(prism::Vec2f(rng.next_float(), rng.next_float())));
  state.SetItemsProcessed(state.iterations());
}

void BM_EnvironmentPdf(benchmark::State& state) {
  const prism::PiecewiseConstant2D d = sky_distribution(static_cast<int>(state.range(0)));
  prism::Pcg32 rng(5, 6);
  for (auto _ : state)
    benchmark::DoNotOptimize(d.pdf(prism::Vec2f(rng.next_float(), rng.next_float())));
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(BM_EnvironmentSample)->Arg(1024)->Arg(2048)->Arg(4096);
BENCHMARK(BM_EnvironmentPdf)->Arg(1024)->Arg(4096);
