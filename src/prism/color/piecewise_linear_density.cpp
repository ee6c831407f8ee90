// Piecewise-linear density with exact inverse-CDF sampling (see piecewise_linear_density.h).
#include "prism/color/piecewise_linear_density.h"

#include <algorithm>
#include <cmath>

#include "prism/core/error.h"

namespace prism::color {

PiecewiseLinearDensity::PiecewiseLinearDensity(double first, double step, std::vector<double> values)
    : first_(first), step_(step), inverse_step_(1.0 / step), pdf_(std::move(values)) {
  if (pdf_.size() < 2 || !(step_ > 0.0)) throw UsageError("piecewise-linear density needs two nodes and a step > 0");
  cdf_.assign(pdf_.size(), 0.0);
  for (std::size_t n = 1; n < pdf_.size(); ++n) {
    if (!(pdf_[n] >= 0.0) || !(pdf_[n - 1] >= 0.0)) throw UsageError("piecewise-linear density: negative value");
    cdf_[n] = cdf_[n - 1] + 0.5 * step_ * (pdf_[n - 1] + pdf_[n]);
  }
  const double total = cdf_.back();
  if (!(total > 0.0)) throw UsageError("piecewise-linear density integrates to 0");
  for (double& p : pdf_) p /= total;
  for (double& c : cdf_) c /= total;
  cdf_.back() = 1.0;
  // About four guide cells per segment: the segment search then scans 0–2 nodes.
  const std::size_t cells = 4 * (pdf_.size() - 1);
  guide_.resize(cells);
  std::size_t segment = 0;
  for (std::size_t g = 0; g < cells; ++g) {
    const double u = double(g) / double(cells);
    while (segment + 2 < cdf_.size() && cdf_[segment + 1] <= u) ++segment;
    guide_[g] = static_cast<int>(segment);
  }
}

double PiecewiseLinearDensity::pdf(double x) const {
  const double position = (x - first_) * inverse_step_;
  const double last_segment = double(pdf_.size() - 2);
  if (!(position >= 0.0) || position > last_segment + 1.0) return 0.0;
  const std::size_t n = static_cast<std::size_t>(std::min(position, last_segment));
  const double t = position - double(n);
  return pdf_[n] + t * (pdf_[n + 1] - pdf_[n]);
}

double PiecewiseLinearDensity::sample(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  const std::size_t cells = guide_.size();
  std::size_t n = static_cast<std::size_t>(guide_[std::min(cells - 1, static_cast<std::size_t>(u * double(cells)))]);
  while (n + 2 < cdf_.size() && cdf_[n + 1] <= u) ++n;
  // In the segment the density is p0 + (p1 − p0)·t, t ∈ [0, 1], so the CDF rises by
  // step·(p0·t + (p1 − p0)·t²/2). Solve for the remaining mass r; the form 2c/(b + √(b² + 4ac))
  // of the quadratic's root has no cancellation when p1 ≈ p0.
  const double p0 = pdf_[n], p1 = pdf_[n + 1];
  const double r = (u - cdf_[n]) * inverse_step_;
  const double a = 0.5 * (p1 - p0), b = p0;
  const double discriminant = std::max(0.0, b * b + 4.0 * a * r);
  const double denominator = b + std::sqrt(discriminant);
  const double t = denominator > 0.0 ? std::clamp(2.0 * r / denominator, 0.0, 1.0) : 0.0;
  return first_ + step_ * (double(n) + t);
}

}  // namespace prism::color
