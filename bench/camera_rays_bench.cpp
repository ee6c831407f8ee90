// Camera rays through Embree ray streams, incoherent (each ray traversed alone, as the
// integrator traces its queues past the camera) against coherent (Embree's packet traversal): the rays of
// a wavefront tile (16 rows of a 256² Cornell box, jittered in their pixels) in pixel
// order, all of them (a tile's first step) or a random 30 % (the paths that restart at a
// later step); and as the integrator traces them, in fixed packets of eight neighbouring
// pixels (EmbreeAccel::intersect_packet; docs/performance-design.md "Camera rays in fixed packets").
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/core/pcg32.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/camera_rays.h"

namespace {

// The camera rays of rows 120–135 of a 256² Cornell box, jittered in their pixels, in
// pixel order.
std::vector<prism::Ray> tile_camera_rays(const prism::Scene& scene, prism::Pcg32& rng) {
  constexpr int kWidth = 256, kTileRows = 16, kFirstRow = 120;
  const prism::PinholeCamera camera(scene.camera, kWidth, kWidth);
  std::vector<prism::Ray> rays;
  for (int y = kFirstRow; y < kFirstRow + kTileRows; ++y)
    for (int x = 0; x < kWidth; ++x)
      rays.push_back(camera.generate_ray(static_cast<float>(x) + rng.next_float(),
                                         static_cast<float>(y) + rng.next_float()));
  return rays;
}

// Args: the percentage of the tile's pixels in the queue; 1 for coherent streams.
void BM_CameraRayStreams(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  prism::Pcg32 rng(3, 4);
  const std::vector<prism::Ray> rays = tile_camera_rays(scene, rng);
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

// The same tile's camera rays as fixed packets of eight neighbouring pixels in a row
// (EmbreeAccel::intersect_packet), every lane traced.
void BM_CameraRayPackets(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  prism::Pcg32 rng(3, 4);
  const std::vector<prism::Ray> rays = tile_camera_rays(scene, rng);
  constexpr std::size_t kPacket = prism::EmbreeAccel::kPacketRays;
  std::vector<prism::Hit> hits(rays.size());
  std::vector<std::uint8_t> found(rays.size());
  for (auto _ : state) {
    for (std::size_t first = 0; first < rays.size(); first += kPacket)
      accel.intersect_packet(rays.data() + first, 0xffu, hits.data() + first, found.data() + first);
    benchmark::DoNotOptimize(found.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays.size()));
}
BENCHMARK(BM_CameraRayPackets);

}  // namespace
