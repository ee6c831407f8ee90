#pragma once
// Chi-square goodness of fit for peaked directional densities. The harness's (cos θ, φ)
// grid cannot resolve a lobe of width 0.05 rad, and its Simpson rule would mis-integrate
// it, so the test runs in a stretched copy of the sphere: the bijection
//   w' = normalize(M w),  M = diag(1/s, 1/s, 1) · R   (R rotates `axis` to +z)
// widens a lobe of angular width ~s around `axis` to width ~1. Densities transform with the
// Jacobian of a linearly transformed direction (Heitz et al. 2016, "Real-Time Polygonal-
// Light Shading with Linearly Transformed Cosines", eq. 18):
//   p'(w') = p(w) · |det M⁻¹| / |M⁻¹ w'|³,  w = M⁻¹ w' / |M⁻¹ w'|.
// A bijection changes neither the distribution's validity nor the test's size, only which
// departures the bins can see. Caveat: unless `axis` is ±z, the horizon (where reflection
// and transmission lobes are cut off) becomes a tilted curve through the bins, which the
// Simpson rule integrates poorly when a lobe presses against it; callers test grazing
// lobes with axis = z (the horizon then stays a bin boundary) and a finer grid instead.
#include <algorithm>
#include <cmath>

#include "prism/core/frame.h"
#include "support/chi_square.h"

namespace prism::test {

inline ChiSquareResult stretched_chi_square(const std::function<bool(Vec2f, Vec3f&)>& sample,
                                            const std::function<double(const Vec3f&)>& pdf,
                                            const Vec3f& axis, float s, long sample_count,
                                            unsigned long long seed, int cos_bins = 20,
                                            int phi_bins = 40, int simpson_intervals = 8) {
  const Frame frame = Frame::from_normal(normalize(axis));
  auto forward = [=](const Vec3f& w) {
    const Vec3f l = frame.to_local(w);
    return normalize(Vec3f(l.x / s, l.y / s, l.z));
  };
  auto inverse = [=](const Vec3f& wp) { return frame.to_world(Vec3f(s * wp.x, s * wp.y, wp.z)); };
  const float sx = s, sy = s;
  const auto h = spherical_histogram(
      [&](Vec2f u, Vec3f& d) {
        Vec3f w;
        if (!sample(u, w)) return false;
        d = forward(w);
        return true;
      },
      [&](const Vec3f& wp) {
        const Vec3f v = inverse(wp);
        const double len = length(Vec3<double>(v));
        return pdf(v / static_cast<float>(len)) * double(sx) * double(sy) / (len * len * len);
      },
      cos_bins, phi_bins, sample_count, seed, simpson_intervals);
  return chi_square_test(h.observed, h.expected);
}

}  // namespace prism::test
