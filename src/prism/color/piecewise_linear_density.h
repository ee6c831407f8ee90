#pragma once
// A 1D density on [first, first + (n−1)·step] that is linear between equally spaced nodes,
// sampled by exact inversion of its (piecewise-quadratic) CDF. Used to tabulate densities
// whose analytic inverse CDF is expensive (the cosh3 wavelength lobes): the tabulated
// density is the one sampled and the one evaluated, so an estimator f(λ)/pdf(λ) that uses
// pdf() below stays exactly unbiased whatever the table's distance from the original.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism::color {

class PiecewiseLinearDensity {
 public:
  // `values` are the unnormalised density at first + i·step (≥ 0, not all 0); they are
  // scaled so that the density integrates to 1 exactly (trapezoid rule = exact integral).
  PiecewiseLinearDensity(double first, double step, std::vector<double> values);

  // Density at x (0 outside the nodes' range).
  double pdf(double x) const;
  // The x with CDF(x) = u, u ∈ [0, 1): finds the segment with the guide table, then solves
  // the quadratic CDF of that segment. Inline: a path's wavelength tuple calls it per slot.
  double sample(double u) const {
    u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
    const std::size_t cells = guide_.size();
    const std::size_t g = static_cast<std::size_t>(u * double(cells));
    std::size_t n = guide_[g < cells ? g : cells - 1];
    // The guide is fine enough that a cell holds at most one node wherever every segment
    // has mass ≥ 1/cells (see the constructor): one branch-free step finds the segment
    // (a data-dependent loop mispredicts on about every other call); the loop is for
    // densities with near-empty segments.
    n += static_cast<std::size_t>(n + 2 < cdf_.size() && cdf_[n + 1] <= u);
    while (n + 2 < cdf_.size() && cdf_[n + 1] <= u) ++n;
    // In the segment the density is p0 + (p1 − p0)·t, t ∈ [0, 1], so the CDF rises by
    // step·(p0·t + (p1 − p0)·t²/2). Solve for the remaining mass r; the form 2c/(b + √(b² + 4ac))
    // of the quadratic's root has no cancellation when p1 ≈ p0.
    const double p0 = pdf_[n], p1 = pdf_[n + 1];
    const double r = (u - cdf_[n]) * inverse_step_;
    const double a = 0.5 * (p1 - p0), b = p0;
    const double discriminant = b * b + 4.0 * a * r;
    const double denominator = b + std::sqrt(discriminant > 0.0 ? discriminant : 0.0);
    double t = denominator > 0.0 ? 2.0 * r / denominator : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return first_ + step_ * (double(n) + t);
  }

  double first() const { return first_; }
  double last() const { return first_ + step_ * double(pdf_.size() - 1); }

 private:
  double first_, step_, inverse_step_;
  std::vector<double> pdf_;    // normalised node values
  std::vector<double> cdf_;    // CDF at each node, cdf_.front() = 0, cdf_.back() = 1
  std::vector<std::uint32_t> guide_;  // guide_[g]: the segment containing u = g / guide_.size()
};

}  // namespace prism::color
