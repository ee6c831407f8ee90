// convergence: relative MSE against a high-spp reference as a function of time and spp,
// per wavelength strategy (hero, cosh, cosh3 with 4 and with 3 wavelengths), and the
// chromaticity error of a white wall region vs spp — to test the seed renderer's claim that
// three cosh lobes reach the converged colour at about 100 spp where hero wavelengths can
// need over 1000. The built-in Cornell box by default; `--scene FILE` renders a scene file
// instead (its own camera, a square image), scoring chromaticity over the whole image.
//
// One render per strategy, one sample per pass; after passes 1, 2, 4, … the film is
// compared with the reference (the comparison's own time is not counted). The reference
// is the mean of two renders with the default strategy (cosh) and other seeds, so its noise
// is independent of every curve's, and measurable (render_reference).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "image_metrics.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/load_scene.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Reference {
  std::vector<Vec3d> srgb, xyz;
  std::vector<char> mask;
  // The reference's own error, estimated from two independent halves: for the average of
  // two renders, E|ref − truth|² ≈ |ref1 − ref2|² / 4, per measure.
  double rel_mse_floor = 0.0, xy_floor = 0.0;
};

// Two default (cosh) renders with independent seeds, averaged; their difference estimates the
// noise the average still carries, which is removed from every curve (in quadrature for
// the xy distance, by subtraction for the relative MSE).
Reference render_reference(const Scene& scene, RenderSettings settings, int spp, int size, const Region& region) {
  settings.samples_per_pixel = spp;
  settings.samples_per_pass = 0;
  settings.transport.wavelength_strategy = TransportSettings{}.wavelength_strategy;
  settings.seed = 0x5eed5eedull;
  const RenderResult a = render(scene, settings);
  settings.seed = 0xfeedf00dull;
  const RenderResult b = render(scene, settings);
  const auto a_srgb = film_linear_srgb(a.film, a.film_space), b_srgb = film_linear_srgb(b.film, b.film_space);
  const auto a_xyz = film_xyz(a.film, a.film_space), b_xyz = film_xyz(b.film, b.film_space);
  Reference ref;
  for (std::size_t i = 0; i < a_srgb.size(); ++i) {
    ref.srgb.push_back((a_srgb[i] + b_srgb[i]) * 0.5);
    ref.xyz.push_back((a_xyz[i] + b_xyz[i]) * 0.5);
  }
  ref.mask = mask_without_lights(ref.xyz);
  ref.rel_mse_floor = relative_mse(a_srgb, b_srgb, ref.mask) / 4.0;
  ref.xy_floor = chromaticity_error(a_xyz, b_xyz, size, size, region).per_pixel_mean / 2.0;
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
  const Scene scene = o.scene.empty() ? make_cornell_box() : load_scene(o.scene);
  const std::string scene_name = o.scene.empty() ? "Cornell box" : o.scene;
  // The box's white back wall; a scene file has no known white region, so the whole image.
  const Region region = o.scene.empty() ? kBackWallRegion : Region{0.0, 0.0, 1.0, 1.0};
  const std::string region_name = o.scene.empty() ? "back-wall" : "whole-image";
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : o.full ? 256 : 128);
  const int max_spp = o.spp > 0 ? o.spp : (o.quick ? 4 : o.full ? 2048 : 256);
  const int ref_spp = o.quick ? 8 : std::max(1024, 4 * max_spp);  // two of these, averaged
  RenderSettings base = cornell_settings(size, max_spp, TransportKind::spectral, o.threads);
  const Reference ref = render_reference(scene, base, ref_spp, size, region);

  Table& curve = report.add_table(
      fmt::format("{} {}^2 spectral, strategy-N = N wavelengths, vs 2 x {}-spp {} reference (its "
                  "noise removed); {} xy error",
                  scene_name, size, ref_spp,
                  color::wavelength_strategy_name(TransportSettings{}.wavelength_strategy), region_name),
      {"strategy", "spp", "seconds", "relMSE", "1/(s*relMSE)", "xy err region mean", "xy err per pixel",
       "xy err per pixel (raw)"});
  Table& summary = report.add_table(
      fmt::format("Per strategy: final relMSE and the spp at which the per-pixel {} chromaticity error first "
                  "drops below a threshold (0: not within the run)",
                  region_name),
      {"strategy", "spp", "seconds", "relMSE", "relMSE x spp", "spp to xy<0.01", "spp to xy<0.005",
       "spp to xy<0.003"});
  nlohmann::json series = nlohmann::json::object();
  struct Variant {
    color::WavelengthStrategy strategy;
    int wavelengths;
  };
  for (const Variant v : {Variant{color::WavelengthStrategy::hero, 4}, Variant{color::WavelengthStrategy::cosh, 4},
                          Variant{color::WavelengthStrategy::cosh3, 4}, Variant{color::WavelengthStrategy::hero, 3},
                          Variant{color::WavelengthStrategy::cosh, 3}, Variant{color::WavelengthStrategy::cosh3, 3}}) {
    const std::string name = fmt::format("{}-{}", color::wavelength_strategy_name(v.strategy), v.wavelengths);
    RenderSettings s = base;
    s.seed = 1;
    s.samples_per_pass = 1;
    s.transport.wavelength_strategy = v.strategy;
    s.transport.wavelengths = v.wavelengths;
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
      const double rel =
          std::max(0.0, relative_mse(film_linear_srgb(film, space), ref.srgb, ref.mask) - ref.rel_mse_floor);
      const ChromaticityError xy = chromaticity_error(film_xyz(film, space), ref.xyz, size, size, region);
      const double xy_pixel =
          std::sqrt(std::max(0.0, xy.per_pixel_mean * xy.per_pixel_mean - ref.xy_floor * ref.xy_floor));
      points.push_back({{"spp", next_sample}, {"seconds", seconds}, {"rel_mse", rel},
                        {"xy_error_region_mean", xy.of_region_mean}, {"xy_error_per_pixel", xy_pixel},
                        {"xy_error_per_pixel_raw", xy.per_pixel_mean}});
      curve.add_row({name, next_sample, seconds, rel, rel > 0 ? 1.0 / (seconds * rel) : 0.0, xy.of_region_mean,
                     xy_pixel, xy.per_pixel_mean});
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
  report.data["scene"] = scene_name;
  report.data["size"] = size;
  report.data["reference_spp"] = ref_spp;
  report.data["reference_rel_mse_floor"] = ref.rel_mse_floor;
  report.data["reference_xy_floor"] = ref.xy_floor;
  report.notes.push_back(fmt::format(
      "relMSE = mean (x - r)^2 / (r^2 + 0.01) over linear-sRGB channels, light pixels excluded, minus the "
      "reference's own {:.3g}; per-pixel xy error: mean CIE xy distance over the {} region, the "
      "reference's own {:.3g} removed in quadrature ('raw' keeps it)",
      ref.rel_mse_floor, region_name, ref.xy_floor));
  report.notes.push_back("one sample per pass (so checkpoints are exact): seconds include per-pass overhead that "
                         "the throughput suite's larger passes avoid");
  return report;
}

}  // namespace prism::bench
