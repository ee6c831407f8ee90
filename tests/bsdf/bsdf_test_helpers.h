#pragma once
// Small helpers the BSDF tests share: directions by angle, RGB spectra, and Monte Carlo
// means with their standard errors.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "prism/color/sampled_spectrum.h"
#include "prism/core/pcg32.h"
#include "prism/core/vec.h"

namespace prism::bsdf::test_helpers {

// The unit direction at polar angle theta and azimuth phi (degrees) about +z.
inline Vec3f direction_at(double theta_deg, double phi_deg = 0.0) {
  const double t = theta_deg * std::numbers::pi / 180.0, p = phi_deg * std::numbers::pi / 180.0;
  return {static_cast<float>(std::sin(t) * std::cos(p)), static_cast<float>(std::sin(t) * std::sin(p)),
          static_cast<float>(std::cos(t))};
}

// The unit direction at polar angle theta (degrees) about +z in the xz-plane (y exactly +0),
// for tests that tilt a direction towards +x only.
inline Vec3f direction_in_xz_plane(double theta_deg) {
  const double t = theta_deg * std::numbers::pi / 180.0;
  return {static_cast<float>(std::sin(t)), 0.0f, static_cast<float>(std::cos(t))};
}

inline color::SampledSpectrum<3> rgb(float r, float g, float b) {
  color::SampledSpectrum<3> s;
  s[0] = r;
  s[1] = g;
  s[2] = b;
  return s;
}

struct Estimate {
  double mean = 0, stderr_ = 0;
};

// The mean of f(rng) over n draws of one PCG32 stream, and its standard error estimated
// from the same draws.
template <typename F>
Estimate monte_carlo(long n, unsigned long long seed, const F& f) {
  Pcg32 rng(seed, 11);
  double sum = 0, sum2 = 0;
  for (long i = 0; i < n; ++i) {
    const double v = f(rng);
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

}  // namespace prism::bsdf::test_helpers
