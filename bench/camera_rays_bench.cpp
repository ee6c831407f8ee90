// Camera rays through Embree ray streams, incoherent (each ray traversed alone, as the
// integrator traces every queue) against coherent (Embree's packet traversal): the rays of
// a wavefront tile (16 rows of a 256² Cornell box, jittered in their pixels) in pixel
// order, all of them (a tile's first step) or a random 30 % (the paths that restart at a
// later step). Time per ray is what the integrator would save by tracing its camera rays
// coherently (BENCHMARKS.md "Session 35").
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/core/pcg32.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/camera_rays.h"

namespace {

// Args: the percentage of the tile's pixels in the queue; 1 for coherent streams.
void BM_CameraRayStreams(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  constexpr int kWidth = 256, kTileRows = 16, kFirstRow = 120;
  const prism::PinholeCamera camera(scene.camera, kWidth, kWidth);
  prism::Pcg32 rng(3, 4);
  std::vector<prism::Ray> rays;
  for (int y = kFirstRow; y < kFirstRow + kTileRows; ++y)
    for (int x = 0; x < kWidth; ++x)
      rays.push_back(camera.generate_ray(static_cast<float>(x) + rng.next_float(),
                                         static_cast<float>(y) + rng.next_float()));
  const float fraction = static_cast<float>(state.range(0)) / 100.0f;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < rays.size(); ++s)
    if (rng.next_float() < fraction) queue.push_back(s);
  const auto coherence = state.range(1) ? prism::RayCoherence::coherent : prism::RayCoherence::incoherent;
  std::vector<prism::Hit> hits(rays.size());
  std::vector<std::uint8_t> found(rays.size());
  for (auto _ : state) {
    accel.intersect_slots(rays.data(), queue.data(), queue.size(), hits.data(), found.data(), coherence);
    benchmark::DoNotOptimize(found.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(queue.size()));
}
BENCHMARK(BM_CameraRayStreams)->ArgNames({"percent", "coherent"})->ArgsProduct({{100, 30}, {0, 1}});

}  // namespace
