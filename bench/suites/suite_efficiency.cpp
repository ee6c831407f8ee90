// efficiency: the peer comparison. Prism renders the Cornell box that pbrt-v4 was
// measured on (512², 64 spp, max depth 8) and its relative MSE is taken against an
// independent higher-spp Prism reference; efficiency = 1 / (seconds × relMSE), as a ratio
// to pbrt-v4's figure quoted in issue 8 (64 spp in 34.6 s, relMSE 0.00175 against a
// 2048-spp reference, on this 2-core machine). pbrt-v4 itself is not run here.
//
// A reference of M spp carries noise of its own: for independent estimates, E[relMSE]
// ≈ σ²(1/n + 1/M). To compare with pbrt's 2048-spp reference the measured value is
// rescaled by (1/n + 1/2048) / (1/n + 1/M) (exact when relMSE is variance-dominated).
#include <fmt/format.h>

#include "image_metrics.h"
#include "prism/scene/builtin_scenes.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {
namespace {

constexpr double kPbrtSeconds = 34.6, kPbrtRelMse = 0.00175, kPbrtReferenceSpp = 2048;
constexpr double kPbrtSamplesPerSecond = 0.49e6, kPbrtRaysPerSecond = 2.05e6;

}  // namespace

SuiteReport run_efficiency_suite(const BenchOptions& o) {
  SuiteReport report{"efficiency"};
  const Scene scene = make_cornell_box();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 512);
  const int spp = o.spp > 0 ? o.spp : (o.quick ? 2 : 64);
  const int ref_spp = o.quick ? 4 : o.full ? 2048 : 256;
  Table& t = report.add_table(
      fmt::format("Cornell box {}^2, {} spp vs {}-spp reference; ratios to pbrt-v4's figures quoted in issue 8", size,
                  spp, ref_spp),
      {"mode", "seconds (total)", "seconds (passes)", "samples/s", "Mrays/s", "relMSE (measured)",
       "relMSE (2048-ref equiv.)", "efficiency 1/(s*relMSE)", "efficiency / pbrt-v4", "samples/s / pbrt-v4",
       "rays/s / pbrt-v4"});
  nlohmann::json rows = nlohmann::json::array();
  for (TransportKind kind : {TransportKind::spectral, TransportKind::rgb}) {
    RenderSettings s = cornell_settings(size, ref_spp, kind, o.threads);
    s.seed = 0x5eed5eedull;
    const RenderResult ref_result = render(scene, s);
    const auto ref = film_linear_srgb(ref_result.film, ref_result.film_space);
    const auto mask = mask_without_lights(film_xyz(ref_result.film, ref_result.film_space));
    // The sampler dimension: every sampler against the same reference (default sampler).
    for (SamplerKind sampler : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol}) {
      s.seed = 1;
      s.samples_per_pixel = spp;
      s.path.sampler = sampler;
      const RenderResult r = render(scene, s);
      const RenderMeasurement m = measure(r);
      const double rel = relative_mse(film_linear_srgb(r.film, r.film_space), ref, mask);
      const double rel2048 = rel * (1.0 / spp + 1.0 / kPbrtReferenceSpp) / (1.0 / spp + 1.0 / ref_spp);
      const double eff = 1.0 / (m.total_seconds * rel2048);
      const double pbrt_eff = 1.0 / (kPbrtSeconds * kPbrtRelMse);
      const std::string label = fmt::format("{} / {}", transport_label(s), sampler_name(sampler));
      t.add_row({label, m.total_seconds, m.render_seconds, m.samples_per_second, m.rays_per_second * 1e-6, rel,
                 rel2048, eff, eff / pbrt_eff, m.samples_per_second / kPbrtSamplesPerSecond,
                 m.rays_per_second / kPbrtRaysPerSecond});
      rows.push_back({{"mode", transport_label(s)}, {"sampler", std::string(sampler_name(sampler))},
                      {"seconds", m.total_seconds}, {"rel_mse", rel}, {"rel_mse_2048_equivalent", rel2048},
                      {"efficiency_ratio_to_pbrt", eff / pbrt_eff}});
    }
  }
  report.data["rows"] = rows;
  report.notes.push_back("pbrt-v4 figures are quoted from issue 8 (0.49 M samples/s, 2.05 M rays/s, 64 spp in "
                         "34.6 s, relMSE 0.00175 vs 2048 spp), not measured in this run; the two renders also differ "
                         "in light units, so relMSE's epsilon weighs dark pixels differently");
  report.notes.push_back("issue 8 goal: efficiency / pbrt-v4 >= 2");
  report.notes.push_back("the reference uses the default sampler; the 2048-spp rescaling assumes variance "
                         "falling as 1/spp, exact for independent sampling and approximate for the others");
  if (o.quick) report.notes.push_back("--quick: sizes are tiny, the ratios to pbrt-v4 are meaningless");
  return report;
}

}  // namespace prism::bench
