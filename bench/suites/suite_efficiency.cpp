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

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "image_metrics.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/load_scene.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {
namespace {

constexpr double kPbrtSeconds = 34.6, kPbrtRelMse = 0.00175, kPbrtReferenceSpp = 2048;
constexpr double kPbrtSamplesPerSecond = 0.49e6;

// One row of the A/B table: a name and what it changes from the default settings.
struct Variant {
  std::string name;
  std::function<void(RenderSettings&)> apply;
  bool spectral_only = false;
};

std::vector<Variant> variants() {
  return {
      {"default", [](RenderSettings&) {}},
      {"light: no selection-sample reuse (before this branch)",
       [](RenderSettings& s) { s.path.light.reuse_selection_sample = false; }},
      {"light: solid angle (Arvo 1995)",
       [](RenderSettings& s) { s.path.light.triangle = TriangleLightSampling::solid_angle; }},
      {"light: solid angle + receiver-cosine warp",
       [](RenderSettings& s) { s.path.light.triangle = TriangleLightSampling::solid_angle_cosine; }},
      {"roulette from bounce 2 (pbrt-v4)", [](RenderSettings& s) { s.path.russian_roulette_depth = 2; }},
      {"wavelengths: cosh3 (three lobes, the earlier default)",
       [](RenderSettings& s) { s.transport.wavelength_strategy = color::WavelengthStrategy::cosh3; }, true},
      {"sampler: independent", [](RenderSettings& s) { s.path.sampler = SamplerKind::independent; }},
      {"sampler: zsobol", [](RenderSettings& s) { s.path.sampler = SamplerKind::zsobol; }},
  };
}

}  // namespace

SuiteReport run_efficiency_suite(const BenchOptions& o) {
  SuiteReport report{"efficiency"};
  // The built-in box, or a scene file through its loader (the comparison renders
  // cornell-box.pbrt; its glossy/glass variant has no pbrt-v4 figure yet).
  const Scene scene = o.scene.empty() ? make_cornell_box() : load_scene(o.scene);
  const std::string scene_name = o.scene.empty() ? "Cornell box (built-in)" : o.scene;
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 512);
  const int spp = o.spp > 0 ? o.spp : (o.quick ? 2 : 64);
  const int ref_spp = o.quick ? 4 : o.full ? 2048 : 256;
  Table& t = report.add_table(
      fmt::format("{} {}^2, {} spp vs {}-spp reference; ratios to pbrt-v4's figures quoted in issue 8, and "
                  "to this run's default row",
                  scene_name, size, spp, ref_spp),
      {"mode", "variant", "seconds (total)", "samples/s", "Mrays/s", "relMSE (measured)", "relMSE (2048-ref equiv.)",
       "efficiency 1/(s*relMSE)", "efficiency / pbrt-v4", "relMSE / default", "efficiency / default",
       "samples/s / pbrt-v4"});
  nlohmann::json rows = nlohmann::json::array();
  for (TransportKind kind : {TransportKind::spectral, TransportKind::rgb}) {
    RenderSettings s = cornell_settings(size, ref_spp, kind, o.threads);
    s.seed = 0x5eed5eedull;
    const RenderResult ref_result = render(scene, s);
    const auto ref = film_linear_srgb(ref_result.film, ref_result.film_space);
    const auto mask = mask_without_lights(film_xyz(ref_result.film, ref_result.film_space));
    // Every variant against the same reference (default settings): all are unbiased, so
    // they converge to the same image.
    double default_rel = 0.0, default_eff = 0.0;
    for (const Variant& variant : variants()) {
      if (variant.spectral_only && kind != TransportKind::spectral) continue;
      RenderSettings v = cornell_settings(size, spp, kind, o.threads);
      v.seed = 1;
      variant.apply(v);
      const RenderResult r = render(scene, v);
      // --repeat: the same render again (fixed seed: the same image and relMSE); the run
      // with the median time gives the rates.
      std::vector<RenderMeasurement> runs{measure(r)};
      for (int k = 1; k < o.repeat; ++k) runs.push_back(measure(render(scene, v)));
      std::sort(runs.begin(), runs.end(),
                [](const RenderMeasurement& a, const RenderMeasurement& b) { return a.total_seconds < b.total_seconds; });
      const RenderMeasurement m = runs[runs.size() / 2];
      const double rel = relative_mse(film_linear_srgb(r.film, r.film_space), ref, mask);
      const double rel2048 = rel * (1.0 / spp + 1.0 / kPbrtReferenceSpp) / (1.0 / spp + 1.0 / ref_spp);
      const double eff = 1.0 / (m.total_seconds * rel2048);
      const double pbrt_eff = 1.0 / (kPbrtSeconds * kPbrtRelMse);
      if (default_rel == 0.0) {
        default_rel = rel;
        default_eff = eff;
      }
      t.add_row({transport_label(v), variant.name, m.total_seconds, m.samples_per_second,
                 m.rays_per_second * 1e-6, rel, rel2048, eff, eff / pbrt_eff, rel / default_rel, eff / default_eff,
                 m.samples_per_second / kPbrtSamplesPerSecond});
      rows.push_back({{"mode", transport_label(v)}, {"variant", variant.name}, {"seconds", m.total_seconds},
                      {"samples_per_second", m.samples_per_second}, {"rel_mse", rel},
                      {"rel_mse_2048_equivalent", rel2048}, {"efficiency_ratio_to_pbrt", eff / pbrt_eff},
                      {"rel_mse_ratio_to_default", rel / default_rel},
                      {"efficiency_ratio_to_default", eff / default_eff}});
    }
  }
  report.data["rows"] = rows;
  report.notes.push_back("pbrt-v4 figures are quoted from issue 8 (0.49 M samples/s, 2.05 M rays/s, 64 spp in "
                         "34.6 s, relMSE 0.00175 vs 2048 spp), not measured in this run; the two renders also differ "
                         "in light units, so relMSE's epsilon weighs dark pixels differently");
  report.notes.push_back("issue 8 goal: efficiency / pbrt-v4 >= 2");
  if (!o.scene.empty())
    report.notes.push_back("pbrt-v4's quoted figures are for the Cornell box: the ratios to them mean something for "
                           "data/scenes/cornell-box.pbrt only");
  report.notes.push_back("the reference uses the default settings; the 2048-spp rescaling assumes variance "
                         "falling as 1/spp, exact for independent sampling and approximate for the others");
  report.notes.push_back(fmt::format("seconds: the median of {} run(s) of each render (--repeat) on a shared machine: "
                                     "compare rows of one run; relMSE ratios are deterministic, time ratios are not",
                                     o.repeat));
  if (o.quick) report.notes.push_back("--quick: sizes are tiny, the ratios to pbrt-v4 are meaningless");
  return report;
}

}  // namespace prism::bench
