#include "prism/display/exposure.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "prism/core/error.h"

namespace prism::display {
namespace {

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v)) throw UsageError(std::string(what) + " must be a positive number");
}

void require_finite_ev(double ev) {
  if (!std::isfinite(ev)) throw UsageError("EV100 must be a finite number");
}

}  // namespace

double ev100_from_camera(double f_number, double shutter_s, double iso) {
  require_positive(f_number, "f-number");
  require_positive(shutter_s, "shutter time");
  require_positive(iso, "ISO");
  return std::log2(f_number * f_number / shutter_s * 100.0 / iso);
}

double max_luminance_nits_from_ev100(double ev) {
  require_finite_ev(ev);
  return 1.2 * std::exp2(ev);
}

double exposure_scale_from_ev100(double ev) { return 1.0 / max_luminance_nits_from_ev100(ev); }

double log_average_luminance(const std::vector<float>& rgb, const Vec3d& w, double delta) {
  const std::size_t n = rgb.size() / 3;
  if (n == 0) return 0.0;
  double sum = 0.0;
  std::size_t counted = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = w.x * rgb[3 * i] + w.y * rgb[3 * i + 1] + w.z * rgb[3 * i + 2];
    if (!std::isfinite(y)) continue;  // NaN/inf pixels would poison the average
    sum += std::log(delta + std::max(y, 0.0));
    ++counted;
  }
  return counted ? std::exp(sum / static_cast<double>(counted)) : 0.0;
}

double auto_exposure_ev100(double log_avg, double key) {
  require_positive(key, "auto-exposure key");
  if (!(log_avg > 0.0) || !std::isfinite(log_avg)) return 0.0;  // black image: EV 0
  return std::log2(log_avg / (1.2 * key));
}

}  // namespace prism::display
