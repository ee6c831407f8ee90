#pragma once
// A 1D density on [first, first + (n−1)·step] that is linear between equally spaced nodes,
// sampled by exact inversion of its (piecewise-quadratic) CDF. Used to tabulate densities
// whose analytic inverse CDF is expensive (the cosh3 wavelength lobes): the tabulated
// density is the one sampled and the one evaluated, so an estimator f(λ)/pdf(λ) that uses
// pdf() below stays exactly unbiased whatever the table's distance from the original.
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
  // the quadratic CDF of that segment.
  double sample(double u) const;

  double first() const { return first_; }
  double last() const { return first_ + step_ * double(pdf_.size() - 1); }

 private:
  double first_, step_, inverse_step_;
  std::vector<double> pdf_;    // normalised node values
  std::vector<double> cdf_;    // CDF at each node, cdf_.front() = 0, cdf_.back() = 1
  std::vector<int> guide_;     // guide_[g]: the segment containing u = g / guide_.size()
};

}  // namespace prism::color
