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
  // Guide cells: at least four per segment, and at least 1/(smallest segment mass), so that
  // no cell holds two nodes and sample() finds its segment in one step (capped at 2^16
  // cells; past that, or across empty segments, the search loops over the extra nodes).
  double smallest_mass = 1.0;
  for (std::size_t n = 1; n < cdf_.size(); ++n) smallest_mass = std::min(smallest_mass, cdf_[n] - cdf_[n - 1]);
  std::size_t cells = 4 * (pdf_.size() - 1);
  if (smallest_mass > 0.0) cells = std::max(cells, static_cast<std::size_t>(std::min(65536.0, 1.0 / smallest_mass)) + 1);
  guide_.resize(cells);
  std::size_t segment = 0;
  for (std::size_t g = 0; g < cells; ++g) {
    const double u = double(g) / double(cells);
    while (segment + 2 < cdf_.size() && cdf_[segment + 1] <= u) ++segment;
    guide_[g] = static_cast<std::uint32_t>(segment);
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

}  // namespace prism::color
