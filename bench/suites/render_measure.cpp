#include "render_measure.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace prism::bench {

RenderMeasurement measure(const RenderResult& result) {
  RenderMeasurement m;
  m.render_seconds = std::accumulate(result.pass_seconds.begin(), result.pass_seconds.end(), 0.0);
  m.total_seconds = result.elapsed_seconds;
  const double samples = static_cast<double>(result.passes_done) * static_cast<double>(result.film.pixel_count());
  m.rays = result.rays;
  m.shadow_rays = result.shadow_rays;
  const double rays = static_cast<double>(result.rays + result.shadow_rays);
  if (m.render_seconds > 0) {
    m.samples_per_second = samples / m.render_seconds;
    m.rays_per_second = rays / m.render_seconds;
  }
  m.rays_per_sample = samples > 0 ? rays / samples : 0.0;
  m.camera_packet_rays_per_sample = samples > 0 ? static_cast<double>(result.camera_packet_rays) / samples : 0.0;
  return m;
}

RenderSettings cornell_settings(int size, int spp, TransportKind kind, int threads) {
  RenderSettings s;
  s.width = s.height = size;
  s.samples_per_pixel = spp;
  s.threads = threads;
  s.transport.kind = kind;
  return s;
}

std::string transport_label(const RenderSettings& settings) {
  if (settings.transport.kind == TransportKind::rgb) return "rgb";
  return describe(settings.transport);
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double coefficient_of_variation(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  const double mu = mean(values);
  double ss = 0.0;
  for (double v : values) ss += (v - mu) * (v - mu);
  const double sd = std::sqrt(ss / static_cast<double>(values.size() - 1));
  return mu > 0 ? sd / mu : 0.0;
}

}  // namespace prism::bench
