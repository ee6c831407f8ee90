#include "secondary_rays.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "prism/core/frame.h"
#include "prism/core/parallel.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"
#include "prism/scene/camera_rays.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"

namespace prism::bench {
namespace {

// The integrator's origin offset (render/surface_interaction.h), restated so that this
// instrument does not move when that header does: off the surface along the normal, to
// the side `direction` leaves towards, scaled to the coordinates' magnitude.
Vec3f offset_origin(const Vec3f& p, const Vec3f& n, const Vec3f& direction) {
  const float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
  return p + (dot(direction, n) >= 0.0f ? n : -n) * (magnitude * 1e-5f);
}

struct SurfacePoint {
  Vec3f position, normal;  // normal: unit, front face (counter-clockwise)
};

SurfacePoint surface_point(const Scene& scene, const Hit& hit) {
  const TriangleMesh& mesh = scene.meshes[hit.mesh];
  const Vec3f& p0 = mesh.positions[mesh.indices[3 * hit.triangle]];
  const Vec3f& p1 = mesh.positions[mesh.indices[3 * hit.triangle + 1]];
  const Vec3f& p2 = mesh.positions[mesh.indices[3 * hit.triangle + 2]];
  return {p0 * (1.0f - hit.u - hit.v) + p1 * hit.u + p2 * hit.v, normalize(cross(p1 - p0, p2 - p0))};
}

}  // namespace

SecondaryRays make_secondary_rays(const Scene& scene, const EmbreeAccel& accel, std::size_t count,
                                  std::uint64_t seed) {
  constexpr int kWidth = 512, kMaxBounces = 7;
  const PinholeCamera camera(scene.camera, kWidth, kWidth);
  const LightSampler lights(scene, scene_bounds(scene));
  Pcg32 rng(seed, 1);
  SecondaryRays out;
  out.closest.reserve(count);
  out.shadow.reserve(count);
  int attempts = 0;
  while (out.closest.size() < count && ++attempts < static_cast<int>(count) * 16) {
    Ray ray = camera.generate_ray(rng.next_float() * kWidth, rng.next_float() * kWidth);
    Hit hit;
    for (int bounce = 0; bounce < kMaxBounces && out.closest.size() < count; ++bounce) {
      if (!accel.intersect(ray, hit)) break;
      const SurfacePoint si = surface_point(scene, hit);
      const Vec3f n = dot(si.normal, ray.direction) < 0.0f ? si.normal : -si.normal;
      if (!lights.empty()) {
        if (const auto ls = lights.sample(si.position, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
            ls && ls->pdf > 0.0f && !std::isinf(ls->distance)) {
          const Vec3f origin = offset_origin(si.position, si.normal, ls->wi);
          const Vec3f target = ls->is_delta ? ls->position : offset_origin(ls->position, ls->normal, -ls->wi);
          const Vec3f segment = target - origin;
          const float len = length(segment);
          if (len > 0.0f) out.shadow.push_back(Ray{origin, segment / len, 0.0f, len * (1.0f - 1e-4f)});
        }
      }
      const Vec3f local = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
      const Vec3f wi = Frame::from_normal(n).to_world(local);
      ray = Ray{offset_origin(si.position, si.normal, wi), wi};
      out.closest.push_back(ray);
    }
  }
  return out;
}

double trace_rays_per_second(const EmbreeAccel& accel, const std::vector<Ray>& rays, bool occlusion, int threads,
                             double min_seconds, bool streams) {
  if (rays.empty()) return 0.0;
  const ThreadLimit limit(threads);
  std::atomic<std::uint64_t> hits{0};
  const auto start = std::chrono::steady_clock::now();
  double seconds = 0.0;
  std::uint64_t traced = 0;
  // Stream queries write per slot: identity slots, one result array for the whole set.
  std::vector<std::uint32_t> slots(streams ? rays.size() : 0);
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<std::uint32_t>(i);
  std::vector<Hit> stream_hits(streams && !occlusion ? rays.size() : 0);
  std::vector<std::uint8_t> answers(streams ? rays.size() : 0), pending(streams ? rays.size() : 0, 1);
  do {
    parallel_for(rays.size(), streams ? 1024 : 2048, [&](std::size_t begin, std::size_t end) {
      std::uint64_t local = 0;
      if (streams) {
        if (occlusion)
          accel.occluded_slots(rays.data(), slots.data() + begin, end - begin, pending.data(), answers.data());
        else
          accel.intersect_slots(rays.data(), slots.data() + begin, end - begin, stream_hits.data(), answers.data());
        for (std::size_t i = begin; i < end; ++i) local += answers[i];
      } else {
        Hit hit;
        for (std::size_t i = begin; i < end; ++i)
          local += occlusion ? accel.occluded(rays[i]) : accel.intersect(rays[i], hit);
      }
      hits.fetch_add(local, std::memory_order_relaxed);
    });
    traced += rays.size();
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (seconds < min_seconds);
  return seconds > 0 ? static_cast<double>(traced) / seconds : 0.0;
}

}  // namespace prism::bench
