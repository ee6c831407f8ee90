// Microbenchmarks of the foundation's renderer: raw Embree throughput for incoherent
// rays in the Cornell box (the ray-tracing limit) and the path tracer's samples/s.
// Run: build/release/bench/prism_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/core/frame.h"
#include "prism/core/pcg32.h"
#include "prism/render/renderer.h"
#include "prism/sampling/warps.h"
#include "prism/scene/builtin_scenes.h"

namespace {

// Rays from points on the Cornell box's surfaces in cosine-distributed directions: the
// distribution of the path tracer's secondary bounces, without any shading work.
std::vector<prism::Ray> secondary_rays(const prism::EmbreeAccel& accel) {
  prism::Pcg32 rng(1, 2);
  const prism::Vec3f origin(278.0f, 273.0f, -800.0f);
  std::vector<prism::Ray> rays;
  while (rays.size() < 1 << 16) {
    // Find surface points by shooting camera-like rays, then bounce once.
    const prism::Vec3f dir = prism::normalize(prism::Vec3f(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 1.0f));
    prism::Hit hit;
    if (!accel.intersect(prism::Ray{origin, dir}, hit)) continue;
    const prism::Vec3f p = origin + dir * (hit.t * 0.999f);
    const prism::Vec3f local = prism::sample_cosine_hemisphere(prism::Vec2f(rng.next_float(), rng.next_float()));
    rays.push_back(prism::Ray{p, prism::Frame::from_normal(-dir).to_world(local)});
  }
  return rays;
}

void BM_EmbreeIncoherentClosestHit(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  const std::vector<prism::Ray> rays = secondary_rays(accel);
  std::size_t i = 0;
  for (auto _ : state) {
    prism::Hit hit;
    benchmark::DoNotOptimize(accel.intersect(rays[i++ & (rays.size() - 1)], hit));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EmbreeIncoherentClosestHit);

// The same rays as a queue of 1024 slots (the integrator's grain) through
// EmbreeAccel::intersect_slots / occluded_slots (Embree ray streams, incoherent flag):
// what the integrator's stages 1 and 3 cost per ray, against the one-ray loop above.
// run_queues hands `trace` successive queues of consecutive slots over `ray_count` rays
// (a power of two) and counts every slot as one item.
template <class Trace>
void run_queues(benchmark::State& state, std::size_t ray_count, Trace&& trace) {
  constexpr std::size_t kQueue = 1024;
  std::vector<std::uint32_t> slots(kQueue);
  std::size_t first = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < kQueue; ++i) slots[i] = static_cast<std::uint32_t>(first + i);
    trace(slots.data(), kQueue);
    first = (first + kQueue) & (ray_count - 1);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kQueue));
}

void BM_EmbreeStreamClosestHit(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  const std::vector<prism::Ray> rays = secondary_rays(accel);
  std::vector<prism::Hit> hits(rays.size());
  std::vector<std::uint8_t> found(rays.size());
  run_queues(state, rays.size(), [&](const std::uint32_t* slots, std::size_t count) {
    accel.intersect_slots(rays.data(), slots, count, hits.data(), found.data());
    benchmark::DoNotOptimize(found.data());
  });
}
BENCHMARK(BM_EmbreeStreamClosestHit);

// Occlusion of the same rays cut to a quarter of their closest-hit distance (the answer
// is then "clear" for most; shadow rays of a path tracer are bounded segments too).
std::vector<prism::Ray> bounded(const prism::EmbreeAccel& accel, std::vector<prism::Ray> rays) {
  for (prism::Ray& r : rays) {
    prism::Hit hit;
    r.t_max = accel.intersect(r, hit) ? 0.25f * hit.t : 1e4f;
  }
  return rays;
}

void BM_EmbreeIncoherentOccluded(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  const std::vector<prism::Ray> rays = bounded(accel, secondary_rays(accel));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(accel.occluded(rays[i++ & (rays.size() - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EmbreeIncoherentOccluded);

void BM_EmbreeStreamOccluded(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  const prism::EmbreeAccel accel(scene);
  const std::vector<prism::Ray> rays = bounded(accel, secondary_rays(accel));
  std::vector<std::uint8_t> pending(rays.size(), 1), blocked(rays.size());
  run_queues(state, rays.size(), [&](const std::uint32_t* slots, std::size_t count) {
    accel.occluded_slots(rays.data(), slots, count, pending.data(), blocked.data());
    benchmark::DoNotOptimize(blocked.data());
  });
}
BENCHMARK(BM_EmbreeStreamOccluded);

void BM_PathTraceCornellBox(benchmark::State& state) {
  const prism::Scene scene = prism::make_cornell_box();
  prism::RenderSettings settings;
  settings.width = settings.height = static_cast<int>(state.range(0));
  settings.samples_per_pixel = 1;
  settings.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(prism::render(scene, settings));
  state.SetItemsProcessed(state.iterations() * settings.width * settings.height);
}
BENCHMARK(BM_PathTraceCornellBox)->Arg(128)->Unit(benchmark::kMillisecond);

}  // namespace
