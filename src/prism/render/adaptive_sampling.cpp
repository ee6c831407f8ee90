#include "prism/render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"

namespace prism {

void validate_adaptive_sampling(const AdaptiveSamplingSettings& s) {
  if (!(s.noise_threshold >= 0.0) || !std::isfinite(s.noise_threshold))
    throw UsageError(fmt::format("--noise-threshold must be 0 (off) or a positive number (got {})", s.noise_threshold));
  if (s.enabled() && s.min_samples < 2)
    throw UsageError(fmt::format("--adaptive-min-samples must be at least 2 (got {})", s.min_samples));
}

AovSet adaptive_film_aovs(const AovSet& requested, const AdaptiveSamplingSettings& settings) {
  AovSet aovs = requested;
  if (settings.enabled()) aovs.variance = true;
  return aovs;
}

int next_adaptive_boundary(const AdaptiveSamplingSettings& settings, int sample, int cap) {
  if (!settings.enabled()) return cap;
  const int n = settings.min_samples;
  const long long next = (static_cast<long long>(sample) / n + 1) * n;
  return next < cap ? static_cast<int>(next) : cap;
}

double relative_luminance_error(const Film& film, std::size_t pixel, const Vec3d& luminance_row, double floor) {
  // variance_of_mean(pixel, M) gives row k of M applied to the covariance; only row 1, the
  // luminance, is used.
  Mat3 m;
  m.m[1] = {luminance_row.x, luminance_row.y, luminance_row.z};
  const double variance = film.variance_of_mean(pixel, m).y;
  if (!(variance > 0.0)) return 0.0;
  const double mean = std::abs(dot(luminance_row, film.mean(pixel)));
  const double denominator = std::max(mean, floor);
  return denominator > 0.0 ? std::sqrt(variance) / denominator : std::numeric_limits<double>::infinity();
}

double mean_image_luminance(const Film& film, const Vec3d& luminance_row) {
  double sum = 0.0;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < film.pixel_count(); ++i) {
    if (film.sample_count(i) == 0) continue;
    sum += dot(luminance_row, film.mean(i));
    ++pixels;
  }
  return pixels > 0 ? sum / static_cast<double>(pixels) : 0.0;
}

std::optional<std::vector<std::uint8_t>> adaptive_active_pixels(const Film& film, const color::ColorSpace& film_space,
                                                                const AdaptiveSamplingSettings& settings,
                                                                int next_sample) {
  if (!settings.enabled() || next_sample < settings.min_samples) return std::nullopt;
  const auto s = static_cast<std::uint32_t>(next_sample);
  std::vector<std::uint8_t> active(film.pixel_count());
  if (next_sample % settings.min_samples != 0) {
    // Between boundaries: the pixels the last boundary kept, which have taken every sample.
    for (std::size_t i = 0; i < active.size(); ++i) active[i] = film.sample_count(i) == s;
    return active;
  }
  const Vec3d luminance_row = film_space.rgb_to_xyz.row(1);
  const double floor = kDarkFloorFraction * std::abs(mean_image_luminance(film, luminance_row));
  // Each pixel's test reads only its own sums: any split across threads gives these bytes.
  std::vector<std::uint8_t> noisy(film.pixel_count());
  parallel_for(noisy.size(), 4096, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i)
      noisy[i] = film.sample_count(i) == s &&
                 relative_luminance_error(film, i, luminance_row, floor) > settings.noise_threshold;
  });
  // Dilated by one pixel (as Cycles does): a pixel next to a noisy one goes on too, so that
  // a pixel whose first samples all missed the light (error 0: all zero) in a noisy region
  // does not stop black while its neighbours are still converging.
  if (!settings.dilate) return noisy;
  const int w = film.width(), h = film.height();
  parallel_for(static_cast<std::size_t>(h), 16, [&](std::size_t row_begin, std::size_t row_end) {
    for (int y = static_cast<int>(row_begin); y < static_cast<int>(row_end); ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        bool any = false;
        for (int dy = std::max(0, y - 1); dy <= std::min(h - 1, y + 1); ++dy)
          for (int dx = std::max(0, x - 1); dx <= std::min(w - 1, x + 1); ++dx)
            any |= noisy[static_cast<std::size_t>(dy) * w + dx] != 0;
        active[i] = film.sample_count(i) == s && any;
      }
  });
  return active;
}

}  // namespace prism
