// limit: the ray-tracing limit (issue 8). Raw Embree rates for the renderer's secondary
// ray distribution, traced with no shading, against the renderer's own rays/s on the same
// scene. Two efficiencies: against the closest-hit rate alone (the definition,
// which flatters the renderer a little because shadow rays are cheaper any-hit queries),
// and against the "mixed" limit — the time raw Embree needs for exactly the renderer's mix
// of closest-hit and shadow rays: (R + S) / (R / rate_closest + S / rate_shadow).
// Raw rates are measured both ways Embree offers for single incoherent rays — one
// rtcIntersect1 / rtcOccluded1 call per ray, and ray streams (rtcIntersect1M /
// rtcOccluded1M with the incoherent flag, as the integrator traces its queues) — and the
// limit is the faster of the two, so the renderer is never compared with a slow baseline.
#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "prism/core/parallel.h"
#include "prism/scene/builtin_scenes.h"
#include "render_measure.h"
#include "secondary_rays.h"
#include "suites.h"

namespace prism::bench {

SuiteReport run_limit_suite(const BenchOptions& o) {
  SuiteReport report{"limit"};
  const Scene scene = make_cornell_box();
  const EmbreeAccel accel(scene);
  const std::size_t ray_count = o.quick ? (1u << 12) : (1u << 19);
  const double min_seconds = o.quick ? 0.0 : 1.0;
  const SecondaryRays rays = make_secondary_rays(scene, accel, ray_count);
  const int all = o.threads > 0 ? o.threads : ThreadLimit::hardware_threads();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 256);
  const int spp = o.spp > 0 ? o.spp : (o.quick ? 1 : 16);

  Table& t = report.add_table(
      fmt::format("Cornell box {}^2, {} spp: raw Embree (one ray per call / ray streams) vs renderer", size, spp),
      {"mode", "threads", "raw closest Mrays/s 1-ray", "raw closest Mrays/s streams", "raw shadow Mrays/s 1-ray",
       "raw shadow Mrays/s streams", "renderer Mrays/s", "rays/sample", "shadow fraction", "efficiency vs closest",
       "efficiency vs mixed"});
  nlohmann::json series = nlohmann::json::array();
  const std::vector<int> thread_counts = all > 1 ? std::vector<int>{1, all} : std::vector<int>{1};
  for (int threads : thread_counts) {
    const double closest_one = trace_rays_per_second(accel, rays.closest, false, threads, min_seconds);
    const double closest_streams = trace_rays_per_second(accel, rays.closest, false, threads, min_seconds, true);
    const double shadow_one = trace_rays_per_second(accel, rays.shadow, true, threads, min_seconds);
    const double shadow_streams = trace_rays_per_second(accel, rays.shadow, true, threads, min_seconds, true);
    const double closest = std::max(closest_one, closest_streams), shadow = std::max(shadow_one, shadow_streams);
    for (TransportKind kind : {TransportKind::spectral, TransportKind::rgb}) {
      const RenderSettings settings = cornell_settings(size, spp, kind, threads);
      const RenderMeasurement m = measure(render(scene, settings));
      const double r = static_cast<double>(m.rays), s = static_cast<double>(m.shadow_rays);
      const double mixed = (r + s) / (r / closest + s / shadow);
      const double shadow_fraction = (r + s) > 0 ? s / (r + s) : 0.0;
      t.add_row({transport_label(settings), threads, closest_one * 1e-6, closest_streams * 1e-6, shadow_one * 1e-6,
                 shadow_streams * 1e-6, m.rays_per_second * 1e-6, m.rays_per_sample, shadow_fraction,
                 m.rays_per_second / closest, m.rays_per_second / mixed});
      series.push_back({{"mode", transport_label(settings)}, {"threads", threads}, {"raw_closest_rays_per_s", closest},
                        {"raw_shadow_rays_per_s", shadow}, {"raw_closest_one_ray_per_call_rays_per_s", closest_one},
                        {"raw_closest_streams_rays_per_s", closest_streams},
                        {"raw_shadow_one_ray_per_call_rays_per_s", shadow_one},
                        {"raw_shadow_streams_rays_per_s", shadow_streams}, {"renderer_rays_per_s", m.rays_per_second},
                        {"efficiency_vs_closest", m.rays_per_second / closest},
                        {"efficiency_vs_mixed", m.rays_per_second / mixed}});
    }
  }
  report.data["rows"] = series;
  report.notes.push_back(fmt::format("{} closest-hit and {} shadow rays: camera rays, then up to 7 cosine bounces "
                                     "about the geometric normal, origins offset as the integrator does",
                                     rays.closest.size(), rays.shadow.size()));
  report.notes.push_back("issue 8 target: efficiency >= 0.70 for the Lambertian Cornell box, spectral");
  return report;
}

}  // namespace prism::bench
