#include "prism/display/exposure_metering.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "prism/color/color_space.h"
#include "prism/core/error.h"

namespace prism::display {
namespace {

constexpr int kZonesAcrossShortSide = 32;
constexpr int kBinsPerEv = 64;
constexpr double kCentreSigma = 0.4;  // of the half-diagonal

struct Zone {
  double log2_y = 0;  // log2 of the coverage-weighted mean luminance
  double weight = 0;  // Σ c_i times the centre weight
};

double centre_weight(double x, double y, int width, int height, double k) {
  if (k <= 0.0) return 1.0;
  const double half_diag = 0.5 * std::hypot(static_cast<double>(width), static_cast<double>(height));
  const double r = std::hypot(x - 0.5 * width, y - 0.5 * height) / half_diag;
  return (1.0 - k) + k * std::exp(-r * r / (2.0 * kCentreSigma * kCentreSigma));
}

// The zones' luminances and weights; `use_coverage` false counts every finite pixel fully.
std::vector<Zone> meter_zones(const ImageRgbF& film, const Vec3d& w, const std::vector<float>& coverage,
                              bool use_coverage, double k, double& covered) {
  const int side = std::max(1, std::min(film.width, film.height) / kZonesAcrossShortSide);
  std::vector<Zone> zones;
  covered = 0;
  for (int y0 = 0; y0 < film.height; y0 += side)
    for (int x0 = 0; x0 < film.width; x0 += side) {
      const int x1 = std::min(film.width, x0 + side), y1 = std::min(film.height, y0 + side);
      double sum_c = 0, sum_cy = 0;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * film.width + x;
          const double lum = w.x * film.rgb[3 * i] + w.y * film.rgb[3 * i + 1] + w.z * film.rgb[3 * i + 2];
          if (!std::isfinite(lum)) continue;
          const double c = use_coverage ? std::clamp(static_cast<double>(coverage[i]), 0.0, 1.0) : 1.0;
          sum_c += c;
          sum_cy += c * std::max(lum, 0.0);
        }
      covered += sum_c;
      if (!(sum_c > 0.0)) continue;
      const double mean = sum_cy / sum_c;
      zones.push_back({mean > 0.0 ? std::log2(mean) : -INFINITY,
                       sum_c * centre_weight(0.5 * (x0 + x1), 0.5 * (y0 + y1), film.width, film.height, k)});
    }
  return zones;
}

// Mean of log2 Y over the weight between the two quantiles of the binned histogram.
double trimmed_log2_mean(const std::vector<Zone>& zones, double lo, double hi, const MeteringSettings& s) {
  const int bins = std::max(1, static_cast<int>(std::ceil((hi - lo) * kBinsPerEv)));
  std::vector<double> histogram(static_cast<std::size_t>(bins), 0.0);
  double total = 0;
  for (const Zone& z : zones) {
    const double pos = (z.log2_y - lo) * kBinsPerEv;  // -inf for black zones
    const int bin = pos < 0 ? 0 : std::min(bins - 1, static_cast<int>(pos));
    histogram[static_cast<std::size_t>(bin)] += z.weight;
    total += z.weight;
  }
  const double from = s.low_percentile * total, to = s.high_percentile * total;
  double below = 0, sum = 0, kept = 0;
  for (int b = 0; b < bins; ++b) {
    const double h = histogram[static_cast<std::size_t>(b)];
    const double overlap = std::max(0.0, std::min(below + h, to) - std::max(below, from));
    sum += overlap * (lo + (b + 0.5) / kBinsPerEv);
    kept += overlap;
    below += h;
  }
  return kept > 0 ? sum / kept : lo;
}

}  // namespace

void validate_metering_settings(const MeteringSettings& s) {
  if (!(s.low_percentile >= 0.0 && s.low_percentile < s.high_percentile && s.high_percentile <= 1.0))
    throw UsageError("metering percentiles must satisfy 0 <= low < high <= 1");
  if (!(s.centre_weight >= 0.0 && s.centre_weight <= 1.0)) throw UsageError("metering centre weight must be in [0, 1]");
  if (!(s.key > 0.0 && std::isfinite(s.key))) throw UsageError("auto-exposure key must be a positive number");
  if (!(std::isfinite(s.ev100_min) && std::isfinite(s.ev100_max) && s.ev100_min < s.ev100_max))
    throw UsageError("the metering EV100 range must be finite with min < max");
}

MeteredExposure meter_exposure(const ImageRgbF& film, const Vec3d& w, const std::vector<float>& coverage,
                               const MeteringSettings& s) {
  validate_metering_settings(s);
  const std::size_t n = static_cast<std::size_t>(film.width) * film.height;
  if (!coverage.empty() && coverage.size() != n)
    throw Error("metering coverage has " + std::to_string(coverage.size()) + " values for " + std::to_string(n) +
                " pixels");
  MeteredExposure out;
  double covered = 0;
  std::vector<Zone> zones = meter_zones(film, w, coverage, !coverage.empty(), s.centre_weight, covered);
  out.covered_fraction = n ? (coverage.empty() ? 1.0 : covered / static_cast<double>(n)) : 0.0;
  if (zones.empty() && !coverage.empty()) zones = meter_zones(film, w, coverage, false, s.centre_weight, covered);
  const bool any_light = std::any_of(zones.begin(), zones.end(), [](const Zone& z) { return z.log2_y > -INFINITY; });
  if (!any_light) return out;  // nothing to meter: EV100 0
  // The histogram spans the luminances the clamp's ends would expose to the key, and one EV
  // beyond each, so that a film outside the range meters outside it and is clamped.
  const double log2_key = std::log2(1.2 * s.key);
  const double log2_y = trimmed_log2_mean(zones, s.ev100_min - 1.0 + log2_key, s.ev100_max + 1.0 + log2_key, s);
  out.metered_luminance_nits = std::exp2(log2_y);
  const double ev = log2_y - log2_key;
  const double clamped = std::clamp(ev, s.ev100_min, s.ev100_max);
  out.clamped = clamped != ev;
  out.ev100 = std::round(clamped * 100.0) / 100.0;
  return out;
}

double median_displayed_luminance(const std::vector<float>& nits, const std::string& primaries, double white_nits,
                                  const std::vector<float>& coverage) {
  const Vec3d w = color::parse_color_space(primaries).rgb_to_xyz.row(1);
  const std::size_t n = nits.size() / 3;
  if (!coverage.empty() && coverage.size() != n) throw Error("median_displayed_luminance: coverage size");
  std::vector<std::pair<double, double>> values;  // (Y / white, weight)
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double c = coverage.empty() ? 1.0 : coverage[i];
    const double y = (w.x * nits[3 * i] + w.y * nits[3 * i + 1] + w.z * nits[3 * i + 2]) / white_nits;
    if (!(c > 0.0) || !std::isfinite(y)) continue;
    values.emplace_back(y, c);
    total += c;
  }
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  double below = 0;
  for (const auto& [y, c] : values) {
    below += c;
    if (below >= 0.5 * total) return y;
  }
  return values.back().first;
}

double adapt_ev100(std::optional<double> shown, double metered, double dt, double speed) {
  if (!shown || !std::isfinite(*shown)) return metered;
  if (std::isinf(speed)) return metered;
  const double keep = std::exp(-std::max(0.0, speed) * std::max(0.0, dt));
  return metered + (*shown - metered) * keep;
}

}  // namespace prism::display
