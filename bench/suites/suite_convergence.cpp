// convergence: relative MSE against a high-spp reference as a function of time and spp,
// per wavelength strategy (hero, cosh, cosh3; 4 wavelengths), and the chromaticity error
// of a white wall region vs spp — to test the seed renderer's claim that three cosh lobes
// reach the converged colour at about 100 spp where hero wavelengths can need over 1000.
//
// One render per strategy, one sample per pass; after passes 1, 2, 4, … the film is
// compared with the reference (the comparison's own time is not counted). The reference
// is cosh3 with another seed, so its noise is independent of every curve's.
#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "image_metrics.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/scene/builtin_scenes.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Reference {
  std::vector<Vec3d> srgb, xyz;
  std::vector<char> mask;
};

Reference render_reference(const Scene& scene, RenderSettings settings, int spp) {
  settings.samples_per_pixel = spp;
  settings.seed = 0x5eed5eedull;
  settings.samples_per_pass = 0;
  settings.transport.wavelength_strategy = color::WavelengthStrategy::cosh3;
  const RenderResult r = render(scene, settings);
  Reference ref{film_linear_srgb(r.film, r.film_space), film_xyz(r.film, r.film_space), {}};
  ref.mask = mask_without_lights(ref.xyz);
  return ref;
}

bool is_checkpoint(int spp, int max_spp) { return (spp & (spp - 1)) == 0 || spp == max_spp; }

// The first spp whose per-pixel chromaticity error is at most `threshold` (0: never).
int spp_to_reach(const nlohmann::json& points, double threshold) {
  for (const auto& p : points)
    if (p["xy_error_per_pixel"].get<double>() <= threshold) return p["spp"].get<int>();
  return 0;
}

}  // namespace

SuiteReport run_convergence_suite(const BenchOptions& o) {
  SuiteReport report{"convergence"};
  const Scene scene = make_cornell_box();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : o.full ? 256 : 128);
  const int max_spp = o.spp > 0 ? o.spp : (o.quick ? 4 : o.full ? 2048 : 256);
  const int ref_spp = o.quick ? 8 : o.full ? 8192 : 1024;
  RenderSettings base = cornell_settings(size, max_spp, TransportKind::spectral, o.threads);
  const Reference ref = render_reference(scene, base, ref_spp);

  Table& curve = report.add_table(
      fmt::format("Cornell box {}^2 spectral (4 wavelengths) vs {}-spp cosh3 reference; back-wall region xy error",
                  size, ref_spp),
      {"strategy", "spp", "seconds", "relMSE", "1/(s*relMSE)", "xy err region mean", "xy err per pixel"});
  Table& summary = report.add_table(
      "Per strategy: final relMSE and the spp at which the per-pixel wall chromaticity error first drops "
      "below a threshold (0: not within the run)",
      {"strategy", "spp", "seconds", "relMSE", "relMSE x spp", "spp to xy<0.01", "spp to xy<0.005",
       "spp to xy<0.003"});
  nlohmann::json series = nlohmann::json::object();
  for (auto strategy : {color::WavelengthStrategy::hero, color::WavelengthStrategy::cosh,
                        color::WavelengthStrategy::cosh3}) {
    const std::string name(color::wavelength_strategy_name(strategy));
    RenderSettings s = base;
    s.seed = 1;
    s.samples_per_pass = 1;
    s.transport.wavelength_strategy = strategy;
    nlohmann::json points = nlohmann::json::array();
    double excluded = 0.0;  // seconds spent scoring, not rendering
    const auto start = Clock::now();
    RenderHooks hooks;
    hooks.checkpoint_interval_seconds = 1e-12;  // every pass
    hooks.on_checkpoint = [&](const Film& film, int next_sample) {
      if (!is_checkpoint(next_sample, max_spp) || (!points.empty() && points.back()["spp"] == next_sample)) return;
      const auto scoring = Clock::now();
      const double seconds = std::chrono::duration<double>(scoring - start).count() - excluded;
      const color::ColorSpace space = film_color_space(s.transport);
      const double rel = relative_mse(film_linear_srgb(film, space), ref.srgb, ref.mask);
      const ChromaticityError xy = chromaticity_error(film_xyz(film, space), ref.xyz, size, size, kBackWallRegion);
      points.push_back({{"spp", next_sample}, {"seconds", seconds}, {"rel_mse", rel},
                        {"xy_error_region_mean", xy.of_region_mean}, {"xy_error_per_pixel", xy.per_pixel_mean}});
      curve.add_row({name, next_sample, seconds, rel, rel > 0 ? 1.0 / (seconds * rel) : 0.0, xy.of_region_mean,
                     xy.per_pixel_mean});
      excluded += std::chrono::duration<double>(Clock::now() - scoring).count();
    };
    render(scene, s, hooks);
    const auto& last = points.back();
    summary.add_row({name, last["spp"], last["seconds"], last["rel_mse"],
                     last["rel_mse"].get<double>() * last["spp"].get<double>(), spp_to_reach(points, 0.01),
                     spp_to_reach(points, 0.005), spp_to_reach(points, 0.003)});
    series[name] = points;
  }
  report.data["series"] = series;
  report.data["size"] = size;
  report.data["reference_spp"] = ref_spp;
  report.notes.push_back(
      "relMSE = mean (x - r)^2 / (r^2 + 0.01) over linear-sRGB channels, light pixels excluded; the reference's "
      "own noise adds about relMSE(ref) = relMSE x spp / reference spp to every point");
  report.notes.push_back("one sample per pass (so checkpoints are exact): seconds include per-pass overhead that "
                         "the throughput suite's larger passes avoid");
  return report;
}

}  // namespace prism::bench
