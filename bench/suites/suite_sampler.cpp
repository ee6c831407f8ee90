// sampler: error against a high-spp reference for each --sampler (independent PCG32,
// padded Owen-scrambled Sobol', blue-noise zsobol) on the Cornell box, at equal spp and at
// equal time, to choose the default by measurement.
//
// One render per sampler, one sample per pass; after passes 1, 2, 4, … the film is scored
// (scoring time excluded). Scores: RMSE and relMSE over linear-sRGB channels, light pixels
// excluded, with the reference's own noise (estimated from its two halves) removed; the
// back wall's chromaticity error (per pixel) as in the convergence suite. Equal time: each
// sampler's log RMSE interpolated (in log seconds) at the time independent sampling took
// for the final spp.
#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "image_metrics.h"
#include "prism/scene/builtin_scenes.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

double mse(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b, const std::vector<char>& mask) {
  double sum = 0.0, n = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!mask[i]) continue;
    for (int c = 0; c < 3; ++c) sum += (a[i][c] - b[i][c]) * (a[i][c] - b[i][c]);
    n += 3.0;
  }
  return n > 0.0 ? sum / n : 0.0;
}

struct Point {
  int spp;
  double seconds, rmse, rel_mse, xy_pixel;
};

// log-log interpolation of RMSE at `seconds` (clamped to the curve's ends).
double rmse_at_time(const std::vector<Point>& curve, double seconds) {
  for (const Point& p : curve)
    if (!(p.rmse > 0.0)) return 0.0;
  if (seconds <= curve.front().seconds) return curve.front().rmse;
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (seconds <= curve[i].seconds) {
      const double t = std::log(seconds / curve[i - 1].seconds) / std::log(curve[i].seconds / curve[i - 1].seconds);
      return std::exp(std::log(curve[i - 1].rmse) + t * std::log(curve[i].rmse / curve[i - 1].rmse));
    }
  return curve.back().rmse;
}

}  // namespace

SuiteReport run_sampler_suite(const BenchOptions& o) {
  SuiteReport report{"sampler"};
  const Scene scene = make_cornell_box();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 128);
  const int max_spp = o.spp > 0 ? o.spp : (o.quick ? 4 : o.full ? 1024 : 256);
  const int ref_spp = o.quick ? 8 : 2048;  // two of these, averaged: a 4096-spp reference
  RenderSettings base = cornell_settings(size, max_spp, TransportKind::spectral, o.threads);

  // Reference: two independent-sampler renders with other seeds, averaged.
  RenderSettings rs = base;
  rs.samples_per_pixel = ref_spp;
  rs.path.sampler = SamplerKind::independent;
  rs.seed = 0x5eed5eedull;
  const RenderResult ra = render(scene, rs);
  rs.seed = 0xfeedf00dull;
  const RenderResult rb = render(scene, rs);
  const auto a_srgb = film_linear_srgb(ra.film, ra.film_space), b_srgb = film_linear_srgb(rb.film, rb.film_space);
  const auto a_xyz = film_xyz(ra.film, ra.film_space), b_xyz = film_xyz(rb.film, rb.film_space);
  std::vector<Vec3d> ref_srgb, ref_xyz;
  for (std::size_t i = 0; i < a_srgb.size(); ++i) {
    ref_srgb.push_back((a_srgb[i] + b_srgb[i]) * 0.5);
    ref_xyz.push_back((a_xyz[i] + b_xyz[i]) * 0.5);
  }
  const std::vector<char> mask = mask_without_lights(ref_xyz);
  // For the average of two independent halves, E|ref − truth|² ≈ |a − b|² / 4.
  const double mse_floor = mse(a_srgb, b_srgb, mask) / 4.0, rel_floor = relative_mse(a_srgb, b_srgb, mask) / 4.0;
  const double xy_floor = chromaticity_error(a_xyz, b_xyz, size, size, kBackWallRegion).per_pixel_mean / 2.0;

  Table& curve = report.add_table(
      fmt::format("Cornell box {}^2 spectral (cosh, 4 wavelengths), vs a 2 x {}-spp independent reference (its "
                  "noise removed)",
                  size, ref_spp),
      {"sampler", "spp", "seconds", "RMSE", "relMSE", "1/(s*relMSE)", "wall xy err per pixel"});
  nlohmann::json series = nlohmann::json::object();
  std::vector<std::vector<Point>> curves;
  const SamplerKind kinds[] = {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol};
  for (SamplerKind kind : kinds) {
    RenderSettings s = base;
    s.seed = 1;
    s.samples_per_pass = 1;
    s.path.sampler = kind;
    std::vector<Point> points;
    double excluded = 0.0;
    const auto start = Clock::now();
    RenderHooks hooks;
    hooks.checkpoint_interval_seconds = 1e-12;  // every pass
    hooks.on_checkpoint = [&](const Film& film, int next) {
      if ((next & (next - 1)) != 0 && next != max_spp) return;
      if (!points.empty() && points.back().spp == next) return;
      const auto scoring = Clock::now();
      const double seconds = std::chrono::duration<double>(scoring - start).count() - excluded;
      const color::ColorSpace space = film_color_space(s.transport);
      const auto srgb = film_linear_srgb(film, space);
      const double e2 = std::max(0.0, mse(srgb, ref_srgb, mask) - mse_floor);
      const double rel = std::max(0.0, relative_mse(srgb, ref_srgb, mask) - rel_floor);
      const double xy = chromaticity_error(film_xyz(film, space), ref_xyz, size, size, kBackWallRegion).per_pixel_mean;
      const double xy_pixel = std::sqrt(std::max(0.0, xy * xy - xy_floor * xy_floor));
      points.push_back({next, seconds, std::sqrt(e2), rel, xy_pixel});
      curve.add_row({std::string(sampler_name(kind)), next, seconds, std::sqrt(e2), rel,
                     rel > 0 ? 1.0 / (seconds * rel) : 0.0, xy_pixel});
      excluded += std::chrono::duration<double>(Clock::now() - scoring).count();
    };
    render(scene, s, hooks);
    nlohmann::json js = nlohmann::json::array();
    for (const Point& p : points)
      js.push_back({{"spp", p.spp}, {"seconds", p.seconds}, {"rmse", p.rmse}, {"rel_mse", p.rel_mse},
                    {"xy_error_per_pixel", p.xy_pixel}});
    series[std::string(sampler_name(kind))] = js;
    curves.push_back(std::move(points));
  }

  Table& ratios = report.add_table(
      "RMSE ratios to independent sampling (below 1: better) at equal spp, and at equal time (the time "
      "independent sampling took for the spp; log-log interpolation of the other curve)",
      {"sampler", "spp", "RMSE / independent (equal spp)", "RMSE / independent (equal time)",
       "seconds / independent"});
  for (std::size_t k = 1; k < curves.size(); ++k)
    for (std::size_t i = 0; i < curves[k].size() && i < curves[0].size(); ++i) {
      const Point& ind = curves[0][i];
      const Point& p = curves[k][i];
      if (!(ind.rmse > 0.0 && p.rmse > 0.0)) continue;  // below the reference's noise (--quick)
      ratios.add_row({std::string(sampler_name(kinds[k])), p.spp, p.rmse / ind.rmse,
                      rmse_at_time(curves[k], ind.seconds) / ind.rmse, p.seconds / ind.seconds});
    }
  report.data["series"] = series;
  report.data["size"] = size;
  report.data["reference_spp"] = 2 * ref_spp;
  report.notes.push_back(fmt::format(
      "RMSE over linear-sRGB channels (nits), light pixels excluded, reference noise removed (MSE floor {:.3g}, "
      "relMSE floor {:.3g}, wall xy floor {:.3g})",
      mse_floor, rel_floor, xy_floor));
  return report;
}

}  // namespace prism::bench
