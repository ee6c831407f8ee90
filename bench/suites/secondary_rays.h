#pragma once
// The ray distribution of the path tracer's secondary bounces, without its shading: camera
// rays through random pixels, then up to seven cosine-weighted bounces about the geometric
// normal from each hit, with origins offset exactly as the integrator offsets them; and at
// every vertex the next-event shadow ray towards a sampled light point. Tracing these
// with no other work measures the ray-tracing limit the renderer is compared against.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/core/ray.h"
#include "prism/scene/scene.h"

namespace prism::bench {

struct SecondaryRays {
  std::vector<Ray> closest;  // continuation rays (closest hit)
  std::vector<Ray> shadow;   // shadow rays (any hit, bounded)
};

SecondaryRays make_secondary_rays(const Scene& scene, const EmbreeAccel& accel, std::size_t count,
                                  std::uint64_t seed = 7);

// Rays traced per second over `rays` with `threads` threads (0: all), repeating the whole
// set until at least min_seconds have passed (always once).
// `streams`: as the integrator traces its queues since the ray-stream change
// (EmbreeAccel::intersect_slots / occluded_slots over 1024-ray chunks); otherwise one
// rtcIntersect1 / rtcOccluded1 call per ray.
double trace_rays_per_second(const EmbreeAccel& accel, const std::vector<Ray>& rays, bool occlusion, int threads,
                             double min_seconds, bool streams = false);

}  // namespace prism::bench
