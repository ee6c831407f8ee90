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
//
// --repeat N runs N rounds, each measuring the raw rates and then both renders, one right
// after the other. The efficiency reported is the median of the rounds' own ratios, and
// its range is given: on a shared machine whose speed drifts in phases of seconds, a ratio
// of two figures taken seconds apart is only as steady as that, and the rounds show it.
#include <algorithm>
#include <iterator>
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

  const int repeat = std::max(1, o.repeat);  // --quick rounds are milliseconds: they run too

  Table& t = report.add_table(
      fmt::format("Cornell box {}^2, {} spp: raw Embree (one ray per call / ray streams) vs renderer, median of {} "
                  "round(s)",
                  size, spp, repeat),
      {"mode", "threads", "raw closest Mrays/s 1-ray", "raw closest Mrays/s streams", "raw shadow Mrays/s 1-ray",
       "raw shadow Mrays/s streams", "renderer Mrays/s", "rays/sample", "camera packet rays/sample", "shadow fraction",
       "efficiency vs closest", "efficiency range", "efficiency vs mixed"});
  nlohmann::json series = nlohmann::json::array();
  const std::vector<int> thread_counts = all > 1 ? std::vector<int>{1, all} : std::vector<int>{1};
  const TransportKind kinds[] = {TransportKind::spectral, TransportKind::rgb};
  for (int threads : thread_counts) {
    // Per round: the four raw rates, then each transport's render and its two efficiencies.
    std::vector<double> closest_one, closest_streams, shadow_one, shadow_streams;
    std::vector<std::vector<RenderMeasurement>> renders(std::size(kinds));
    std::vector<std::vector<double>> efficiency(std::size(kinds)), efficiency_mixed(std::size(kinds));
    for (int round = 0; round < repeat; ++round) {
      closest_one.push_back(trace_rays_per_second(accel, rays.closest, false, threads, min_seconds));
      closest_streams.push_back(trace_rays_per_second(accel, rays.closest, false, threads, min_seconds, true));
      shadow_one.push_back(trace_rays_per_second(accel, rays.shadow, true, threads, min_seconds));
      shadow_streams.push_back(trace_rays_per_second(accel, rays.shadow, true, threads, min_seconds, true));
      const double closest = std::max(closest_one.back(), closest_streams.back());
      const double shadow = std::max(shadow_one.back(), shadow_streams.back());
      for (std::size_t k = 0; k < std::size(kinds); ++k) {
        const RenderMeasurement m = measure(render(scene, cornell_settings(size, spp, kinds[k], threads)));
        const double r = static_cast<double>(m.rays), sh = static_cast<double>(m.shadow_rays);
        renders[k].push_back(m);
        efficiency[k].push_back(m.rays_per_second / closest);
        efficiency_mixed[k].push_back(m.rays_per_second * (r / closest + sh / shadow) / (r + sh));
      }
    }
    const double closest = std::max(median(closest_one), median(closest_streams));
    const double shadow = std::max(median(shadow_one), median(shadow_streams));
    for (std::size_t k = 0; k < std::size(kinds); ++k) {
      const RenderSettings settings = cornell_settings(size, spp, kinds[k], threads);
      const RenderMeasurement& m = renders[k].front();  // ray counts: the same in every round (fixed seed)
      std::vector<double> renderer_rates;
      for (const RenderMeasurement& each : renders[k]) renderer_rates.push_back(each.rays_per_second);
      const double r = static_cast<double>(m.rays), sh = static_cast<double>(m.shadow_rays);
      const double shadow_fraction = (r + sh) > 0 ? sh / (r + sh) : 0.0;
      const auto [lowest, highest] = std::minmax_element(efficiency[k].begin(), efficiency[k].end());
      t.add_row({transport_label(settings), threads, median(closest_one) * 1e-6, median(closest_streams) * 1e-6,
                 median(shadow_one) * 1e-6, median(shadow_streams) * 1e-6, median(renderer_rates) * 1e-6,
                 m.rays_per_sample, m.camera_packet_rays_per_sample, shadow_fraction, median(efficiency[k]),
                 fmt::format("{:.3f}-{:.3f}", *lowest, *highest), median(efficiency_mixed[k])});
      series.push_back({{"mode", transport_label(settings)}, {"threads", threads}, {"rounds", repeat},
                        {"raw_closest_rays_per_s", closest}, {"raw_shadow_rays_per_s", shadow},
                        {"raw_closest_one_ray_per_call_rays_per_s", median(closest_one)},
                        {"raw_closest_streams_rays_per_s", median(closest_streams)},
                        {"raw_shadow_one_ray_per_call_rays_per_s", median(shadow_one)},
                        {"raw_shadow_streams_rays_per_s", median(shadow_streams)},
                        {"renderer_rays_per_s", median(renderer_rates)},
                        {"camera_packet_rays_per_sample", m.camera_packet_rays_per_sample},
                        {"efficiency_vs_closest", median(efficiency[k])},
                        {"efficiency_vs_mixed", median(efficiency_mixed[k])},
                        {"efficiency_vs_closest_per_round", efficiency[k]},
                        {"renderer_rays_per_s_per_round", renderer_rates}});
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
