// Next-event sampling of one emissive triangle (scene/triangle_light_sampling.h) by each
// strategy, from receivers spread over the Cornell box with their wall normals: the cost
// of a sample and of the matching pdf (what MIS pays when BSDF sampling hits the light).
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/core/pcg32.h"
#include "prism/scene/triangle_light_sampling.h"

namespace {

struct Receiver {
  prism::Vec3f position, normal;
};

prism::TriangleLight cornell_light_half() {
  prism::TriangleLight l;
  l.p0 = {213, 548.8f, 227};
  l.e1 = prism::Vec3f(343, 548.8f, 332) - l.p0;  // e1 × e2 points down (-y): the emitting side
  l.e2 = prism::Vec3f(213, 548.8f, 332) - l.p0;
  l.normal = {0, -1, 0};
  l.area = 0.5f * 130 * 105;
  return l;
}

// Points on the floor, the back wall and the two side walls of the box, with their normals.
std::vector<Receiver> receivers() {
  prism::Pcg32 rng(7, 8);
  std::vector<Receiver> r(4096);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const float a = 550.0f * rng.next_float(), b = 540.0f * rng.next_float();
    switch (i % 4) {
      case 0: r[i] = {{a, 0.0f, b}, {0, 1, 0}}; break;
      case 1: r[i] = {{a, b, 559.0f}, {0, 0, -1}}; break;
      case 2: r[i] = {{0.0f, b, a}, {1, 0, 0}}; break;
      default: r[i] = {{555.0f, b, a}, {-1, 0, 0}}; break;
    }
  }
  return r;
}

void BM_TriangleLightSample(benchmark::State& state) {
  const auto strategy = static_cast<prism::TriangleLightSampling>(state.range(0));
  const prism::TriangleLight light = cornell_light_half();
  const std::vector<Receiver> rx = receivers();
  prism::Pcg32 rng(9, 10);
  std::size_t i = 0;
  for (auto _ : state) {
    const Receiver& r = rx[i++ & 4095];
    benchmark::DoNotOptimize(prism::sample_triangle_light(light, strategy, r.position, r.normal,
                                                          prism::Vec2f(rng.next_float(), rng.next_float())));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_TriangleLightPdf(benchmark::State& state) {
  const auto strategy = static_cast<prism::TriangleLightSampling>(state.range(0));
  const prism::TriangleLight light = cornell_light_half();
  const std::vector<Receiver> rx = receivers();
  prism::Pcg32 rng(11, 12);
  std::vector<prism::Vec3f> on_light(4096);
  for (auto& p : on_light) {
    const float s = rng.next_float(), t = rng.next_float();
    p = light.p0 + light.e1 * (s < t ? s : t) + light.e2 * (s < t ? t - s : s - t) * 0.5f;
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const Receiver& r = rx[i & 4095];
    benchmark::DoNotOptimize(prism::triangle_light_pdf(light, strategy, r.position, r.normal, on_light[i & 4095]));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

// 0 area, 1 solid angle (Arvo 1995), 2 solid angle with the receiver-cosine warp (default).
BENCHMARK(BM_TriangleLightSample)->ArgName("strategy")->DenseRange(0, 2);
BENCHMARK(BM_TriangleLightPdf)->ArgName("strategy")->DenseRange(0, 2);

}  // namespace
