#pragma once
// Warp of the unit square to a bilinear density (Hart, Pharr, Müller, Lopes, McGuire,
// Shirley 2020, "Practical Product Sampling by Fitting and Composing Warps", EGSR, §3):
// the density is the bilinear interpolation of four non-negative corner values, normalised;
// sampled as the marginal in y (linear) and then x given y (linear). Composed before a
// square → domain map (the spherical triangle's), it approximates a product, e.g. with
// the cosine at a receiver, and keeps stratification (both steps are monotone).
#include <algorithm>
#include <cmath>

#include "prism/core/vec.h"

namespace prism {

// Corner values: w00 at (0,0), w10 at (1,0), w01 at (0,1), w11 at (1,1).
struct BilinearWeights {
  double w00 = 1.0, w10 = 1.0, w01 = 1.0, w11 = 1.0;
};

// Density on [0,1] proportional to (1 − x)·a + x·b (a, b ≥ 0, not both 0), by inverting
// its CDF (2ax + (b − a)x²)/(a + b) = ξ. The root is written as ξ(a + b)/(a + √(a² + ξ(b² − a²)))
// so that a ≈ b does not cancel.
inline double sample_linear(double xi, double a, double b) {
  if (a == b) return xi;
  const double x = xi * (a + b) / (a + std::sqrt(std::max(0.0, a * a + xi * (b * b - a * a))));
  return std::min(x, 0x1.fffffffffffffp-1);
}

inline double linear_pdf(double x, double a, double b) {
  const double sum = a + b;
  return sum > 0.0 ? 2.0 * ((1.0 - x) * a + x * b) / sum : 1.0;
}

inline double bilinear_pdf(Vec2<double> p, const BilinearWeights& w) {
  const double sum = w.w00 + w.w10 + w.w01 + w.w11;
  if (!(sum > 0.0)) return 1.0;
  const double value = (1.0 - p.x) * (1.0 - p.y) * w.w00 + p.x * (1.0 - p.y) * w.w10 + (1.0 - p.x) * p.y * w.w01 +
                       p.x * p.y * w.w11;
  return 4.0 * value / sum;
}

inline Vec2<double> sample_bilinear(Vec2<double> u, const BilinearWeights& w) {
  const double y = sample_linear(u.y, w.w00 + w.w10, w.w01 + w.w11);
  const double x = sample_linear(u.x, (1.0 - y) * w.w00 + y * w.w01, (1.0 - y) * w.w10 + y * w.w11);
  return {x, y};
}

}  // namespace prism
