#pragma once
// Ray queries against the scene's triangles through an Embree 3 BVH. Embree types stay
// inside the .cpp: the rest of Prism sees only Ray and Hit.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "prism/core/ray.h"
#include "prism/scene/scene.h"

namespace prism {

// How a queue's rays relate, for Embree's ray streams. Incoherent: each ray traversed
// alone. Coherent: Embree's packet traversal, for rays that start together and point
// alike, such as camera rays of neighbouring pixels: about 0.4 × the time a ray on the
// Cornell box's camera rays (bench/camera_rays_bench.cpp; docs/performance-design.md "Camera rays in
// fixed packets").
// A packet computes each ray's hit with the single-ray arithmetic (ray_streams_test),
// except where two triangles are hit at exactly the same distance (a shared edge, a
// duplicated face): which of them it reports depends on the order it visits them in, and
// so on the packet's other rays. The integrator's queues are traced incoherently for that
// reason, and its camera rays in packets that never change (intersect_packet,
// render/camera_packet_cache.h): its images are bitwise independent of which paths share
// a queue (wavefront_integrator.h, "Determinism").
enum class RayCoherence { incoherent, coherent };

struct Hit {
  float t = 0.0f;
  std::uint32_t mesh = 0;      // index into Scene::meshes
  std::uint32_t triangle = 0;  // triangle index within the mesh
  float u = 0.0f, v = 0.0f;    // barycentrics of vertices 1 and 2
};

class EmbreeAccel {
 public:
  // Meshes whose material has alpha coverage (surface_alpha.h) get intersection filters
  // that read `scene` (materials, uvs, textures) during queries: the scene must outlive
  // the accelerator and keep its meshes and textures; which meshes are filtered is fixed
  // here.
  explicit EmbreeAccel(const Scene& scene);
  ~EmbreeAccel();
  EmbreeAccel(const EmbreeAccel&) = delete;
  EmbreeAccel& operator=(const EmbreeAccel&) = delete;

  // Closest hit in (ray.t_min, ray.t_max); false when the ray escapes.
  bool intersect(const Ray& ray, Hit& hit) const;
  // True when anything blocks the segment (ray.t_min, ray.t_max).
  bool occluded(const Ray& ray) const;

  // The same queries over a queue: rays[slots[i]] for i < count, results stored at the
  // same slot (hits[slot], found[slot]; blocked[slot]). Traced as Embree ray streams
  // (rtcIntersect1M / rtcOccluded1M, RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT) of a few dozen
  // rays: one call and one context per stream instead of per ray. intersect_slots writes
  // hits[slot] for a miss too, with meaningless values (found[slot] is 0): no branch on
  // whether a ray hit, a coin flip to the predictor. occluded_slots skips slots whose
  // `pending` flag is 0 and leaves their `blocked` entry alone.
  void intersect_slots(const Ray* rays, const std::uint32_t* slots, std::size_t count, Hit* hits,
                       std::uint8_t* found, RayCoherence coherence = RayCoherence::incoherent) const;
  void occluded_slots(const Ray* rays, const std::uint32_t* slots, std::size_t count, const std::uint8_t* pending,
                      std::uint8_t* blocked) const;
  // The closest hits of rays[0 … 8) traced together as one Embree packet (rtcIntersect8,
  // coherent), lane i where bit i of `lanes` is set; hits[i] and found[i] as in
  // intersect_slots, for every lane (an unset lane reports no hit). A packet's hits
  // depend only on its own rays and lanes (see RayCoherence for why they depend on its
  // other rays at all): callers that must be deterministic always trace the same rays
  // together.
  static constexpr std::size_t kPacketRays = 8;
  void intersect_packet(const Ray* rays, unsigned lanes, Hit* hits, std::uint8_t* found) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace prism
