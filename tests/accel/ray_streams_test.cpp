// The queue queries (EmbreeAccel::intersect_slots / occluded_slots, traced as Embree ray
// streams) against the one-ray queries they replace in the integrator: the same hits and
// the same occlusion answers for every ray, stored at the ray's own slot, whatever the
// queue's order and length. The integrator's bitwise-determinism claim rests on this.
#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "prism/accel/embree_accel.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/camera_rays.h"
#include "support/same_bits.h"

namespace prism {
namespace {

// Rays from random points inside the Cornell box (and a little outside it, so some escape
// through the open front) in uniformly random directions; every third one is a bounded
// segment, so occlusion answers are mixed.
std::vector<Ray> random_rays(std::size_t count) {
  Pcg32 rng(11, 3);
  std::vector<Ray> rays(count);
  for (Ray& r : rays) {
    const Vec3f origin{rng.next_float() * 600.0f - 20.0f, rng.next_float() * 600.0f - 20.0f,
                       rng.next_float() * 700.0f - 50.0f};
    const Vec3f direction = sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float()));
    const float t_max = rng.next_u32() % 3 == 0 ? rng.next_float() * 400.0f : 1e30f;
    r = Ray{origin, direction, 0.0f, t_max};
  }
  return rays;
}

// A queue that visits the slots out of order and leaves some out, with a length that is
// not a multiple of the stream size.
std::vector<std::uint32_t> shuffled_queue(std::size_t slots) {
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < slots; ++s)
    if (s % 7 != 3) queue.push_back(static_cast<std::uint32_t>((s * 40503u) % slots));
  return queue;
}

using test::same_bits;  // support/same_bits.h

TEST(RayStreams, ClosestHitsMatchOneRayQueriesSlotBySlot) {
  const Scene scene = make_cornell_box();
  const EmbreeAccel accel(scene);
  const std::size_t slots = 4099;  // prime: 40503 permutes it
  const std::vector<Ray> rays = random_rays(slots);
  const std::vector<std::uint32_t> queue = shuffled_queue(slots);
  std::vector<Hit> hits(slots);
  std::vector<std::uint8_t> found(slots, 2);  // 2: never written
  accel.intersect_slots(rays.data(), queue.data(), queue.size(), hits.data(), found.data());

  std::size_t hit_count = 0, miss_count = 0;
  for (std::uint32_t s : queue) {
    Hit expected;
    const bool expected_found = accel.intersect(rays[s], expected);
    ASSERT_EQ(found[s], expected_found ? 1 : 0) << "slot " << s;
    if (!expected_found) {
      ++miss_count;
      continue;
    }
    ++hit_count;
    EXPECT_TRUE(same_bits(hits[s].t, expected.t)) << "slot " << s;
    EXPECT_EQ(hits[s].mesh, expected.mesh) << "slot " << s;
    EXPECT_EQ(hits[s].triangle, expected.triangle) << "slot " << s;
    EXPECT_TRUE(same_bits(hits[s].u, expected.u) && same_bits(hits[s].v, expected.v)) << "slot " << s;
  }
  // Both outcomes occur, so the comparison covers both branches.
  EXPECT_GT(hit_count, 100u);
  EXPECT_GT(miss_count, 100u);
  std::size_t untouched = 0;
  for (std::uint8_t f : found) untouched += f == 2;
  EXPECT_EQ(untouched, slots - queue.size());  // slots outside the queue are left alone
}

// Closest hits of a queue traced as `coherence` says, against one-ray queries, bit for bit.
// The camera rays of a 64 × 48 image, jittered in their pixels, in pixel order.
std::vector<Ray> jittered_camera_rays(const Scene& scene, Pcg32& rng) {
  const int width = 64, height = 48;
  const PinholeCamera camera(scene.camera, width, height);
  std::vector<Ray> rays;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      rays.push_back(camera.generate_ray(static_cast<float>(x) + rng.next_float(),
                                         static_cast<float>(y) + rng.next_float()));
  return rays;
}

void expect_one_ray_hits(const EmbreeAccel& accel, const std::vector<Ray>& rays, const std::vector<std::uint32_t>& queue,
                         RayCoherence coherence, std::size_t& hit_count) {
  std::vector<Hit> hits(rays.size());
  std::vector<std::uint8_t> found(rays.size(), 2);
  accel.intersect_slots(rays.data(), queue.data(), queue.size(), hits.data(), found.data(), coherence);
  for (std::uint32_t s : queue) {
    Hit expected;
    const bool expected_found = accel.intersect(rays[s], expected);
    ASSERT_EQ(found[s], expected_found ? 1 : 0) << "slot " << s;
    if (!expected_found) continue;
    ++hit_count;
    EXPECT_TRUE(same_bits(hits[s].t, expected.t)) << "slot " << s;
    EXPECT_EQ(hits[s].mesh, expected.mesh) << "slot " << s;
    EXPECT_EQ(hits[s].triangle, expected.triangle) << "slot " << s;
    EXPECT_TRUE(same_bits(hits[s].u, expected.u) && same_bits(hits[s].v, expected.v)) << "slot " << s;
  }
}

// Coherent streams (Embree's packet traversal) compute each ray's hit with the single-ray
// arithmetic: on camera rays in pixel order, every pixel and a sparse subset (as a queue
// holds the camera rays of the paths that just restarted), and on the random rays.
TEST(RayStreams, CoherentStreamsGiveTheOneRayHits) {
  const Scene scene = make_cornell_box();
  const EmbreeAccel accel(scene);
  Pcg32 rng(5, 9);
  const std::vector<Ray> camera_rays = jittered_camera_rays(scene, rng);
  std::vector<std::uint32_t> every(camera_rays.size()), sparse;
  std::iota(every.begin(), every.end(), 0u);
  for (std::uint32_t s = 0; s < camera_rays.size(); ++s)
    if (rng.next_float() < 0.3f) sparse.push_back(s);
  std::size_t camera_hits = 0, random_hits = 0;
  expect_one_ray_hits(accel, camera_rays, every, RayCoherence::coherent, camera_hits);
  expect_one_ray_hits(accel, camera_rays, sparse, RayCoherence::coherent, camera_hits);
  const std::vector<Ray> rays = random_rays(4099);
  expect_one_ray_hits(accel, rays, shuffled_queue(rays.size()), RayCoherence::coherent, random_hits);
  // Most camera rays see the box, the rest pass beside it (both outcomes are compared);
  // most random rays hit.
  EXPECT_GT(camera_hits, (every.size() + sparse.size()) / 2);
  EXPECT_LT(camera_hits, every.size() + sparse.size());
  EXPECT_GT(random_hits, 1000u);
}

// Fixed packets (EmbreeAccel::intersect_packet, the integrator's camera packets): each
// lane's hit is the one-ray hit, with every lane traced and with a partial packet (the
// image's last block), on camera rays of neighbouring pixels and on random rays; lanes
// left out are not traced.
TEST(RayStreams, PacketsGiveTheOneRayHitsInEveryLane) {
  const Scene scene = make_cornell_box();
  const EmbreeAccel accel(scene);
  Pcg32 rng(7, 3);
  std::vector<Ray> rays = jittered_camera_rays(scene, rng);
  const std::vector<Ray> random = random_rays(1024);
  rays.insert(rays.end(), random.begin(), random.end());
  constexpr std::size_t kLanes = EmbreeAccel::kPacketRays;
  std::size_t hits_seen = 0, misses_seen = 0, packets = 0;
  for (std::size_t first = 0; first + kLanes <= rays.size(); first += kLanes, ++packets) {
    const unsigned lanes = packets % 5 == 4 ? 0x1fu : 0xffu;  // every fifth packet: five lanes
    std::array<Hit, kLanes> hits;
    std::array<std::uint8_t, kLanes> found;
    found.fill(2);
    accel.intersect_packet(rays.data() + first, lanes, hits.data(), found.data());
    for (std::size_t i = 0; i < kLanes; ++i) {
      if (!((lanes >> i) & 1u)) {
        EXPECT_EQ(found[i], 0) << "a lane left out reports no hit";
        continue;
      }
      Hit expected;
      const bool expected_found = accel.intersect(rays[first + i], expected);
      ASSERT_EQ(found[i], expected_found ? 1 : 0) << "ray " << first + i;
      if (!expected_found) {
        ++misses_seen;
        continue;
      }
      ++hits_seen;
      EXPECT_TRUE(same_bits(hits[i].t, expected.t)) << "ray " << first + i;
      EXPECT_EQ(hits[i].mesh, expected.mesh) << "ray " << first + i;
      EXPECT_EQ(hits[i].triangle, expected.triangle) << "ray " << first + i;
      EXPECT_TRUE(same_bits(hits[i].u, expected.u) && same_bits(hits[i].v, expected.v)) << "ray " << first + i;
    }
  }
  EXPECT_GT(hits_seen, 2000u);
  EXPECT_GT(misses_seen, 10u);
}

TEST(RayStreams, OcclusionMatchesOneRayQueriesForPendingSlotsOnly) {
  const Scene scene = make_cornell_box();
  const EmbreeAccel accel(scene);
  const std::size_t slots = 4099;
  const std::vector<Ray> rays = random_rays(slots);
  const std::vector<std::uint32_t> queue = shuffled_queue(slots);
  std::vector<std::uint8_t> pending(slots);
  for (std::size_t s = 0; s < slots; ++s) pending[s] = s % 5 != 0;
  std::vector<std::uint8_t> blocked(slots, 2);
  accel.occluded_slots(rays.data(), queue.data(), queue.size(), pending.data(), blocked.data());

  std::size_t blocked_count = 0, clear_count = 0;
  for (std::uint32_t s : queue) {
    if (!pending[s]) {
      EXPECT_EQ(blocked[s], 2) << "slot " << s << " is not pending and must not be written";
      continue;
    }
    const bool expected = accel.occluded(rays[s]);
    ASSERT_EQ(blocked[s], expected ? 1 : 0) << "slot " << s;
    (expected ? blocked_count : clear_count) += 1;
  }
  EXPECT_GT(blocked_count, 100u);
  EXPECT_GT(clear_count, 100u);
}

TEST(RayStreams, EmptyAndAllIdleQueuesTraceNothing) {
  const Scene scene = make_cornell_box();
  const EmbreeAccel accel(scene);
  const std::vector<Ray> rays = random_rays(8);
  std::vector<std::uint32_t> queue(8);
  std::iota(queue.begin(), queue.end(), 0u);
  std::vector<Hit> hits(8);
  std::vector<std::uint8_t> found(8, 2), pending(8, 0), blocked(8, 2);
  accel.intersect_slots(rays.data(), queue.data(), 0, hits.data(), found.data());
  accel.occluded_slots(rays.data(), queue.data(), queue.size(), pending.data(), blocked.data());
  for (std::size_t s = 0; s < 8; ++s) {
    EXPECT_EQ(found[s], 2);
    EXPECT_EQ(blocked[s], 2);
  }
}

}  // namespace
}  // namespace prism
