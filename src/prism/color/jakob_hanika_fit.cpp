// Gauss–Newton fit of sigmoid-polynomial spectra in CIELAB (Jakob & Hanika 2019, §4) and
// the coefficient-table generator.
#include "prism/color/jakob_hanika_fit.h"

#include <atomic>
#include <algorithm>
#include <cmath>
#include <mutex>

#include <tbb/parallel_for.h>

#include "prism/color/cielab.h"

namespace prism::color {
namespace {

constexpr double kFirstNm = kVisibleMinNm;
constexpr double kSpanNm = kVisibleRangeNm;

// d/dt of CIELAB's f(t) (CIE 15:2004 eq. 8.7): the cube root, or the linear segment.
double lab_f_derivative(double t) {
  constexpr double delta = 6.0 / 29.0;
  if (t > delta * delta * delta) return 1.0 / (3.0 * std::cbrt(t * t));
  return 1.0 / (3.0 * delta * delta);
}

// ∂Lab/∂XYZ at xyz.
Mat3 lab_jacobian(const Vec3d& xyz, const Vec3d& white) {
  const double dx = lab_f_derivative(xyz.x / white.x) / white.x;
  const double dy = lab_f_derivative(xyz.y / white.y) / white.y;
  const double dz = lab_f_derivative(xyz.z / white.z) / white.z;
  Mat3 j;
  j.m = {{{0.0, 116.0 * dy, 0.0}, {500.0 * dx, -500.0 * dy, 0.0}, {0.0, 200.0 * dy, -200.0 * dz}}};
  return j;
}

}  // namespace

SigmoidPolynomial to_wavelength_nm(const NormalizedCoefficients& c) {
  // Substitute t = (λ − a)/s into c₀t² + c₁t + c₂ and collect powers of λ.
  const double a = kFirstNm, s = kSpanNm;
  return {c[0] / (s * s), c[1] / s - 2.0 * a * c[0] / (s * s),
          c[0] * a * a / (s * s) - c[1] * a / s + c[2]};
}

JakobHanikaFitter::JakobHanikaFitter(const DenseSpectrum& illuminant, double step_nm) {
  const int steps = static_cast<int>(kSpanNm / step_nm + 0.5);
  double y_integral = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double nm = kFirstNm + i * step_nm;
    const double weight = (i == 0 || i == steps ? 0.5 : 1.0) * step_nm * illuminant(nm);
    t_.push_back((nm - kFirstNm) / kSpanNm);
    weights_.push_back(cie1931_xyz_bar(nm) * weight);
    y_integral += weights_.back().y;
  }
  for (Vec3d& w : weights_) w /= y_integral;
  for (const Vec3d& w : weights_) white_xyz_ += w;
}

void JakobHanikaFitter::evaluate(const NormalizedCoefficients& c, Vec3d& xyz, Mat3& jacobian) const {
  xyz = {};
  Vec3d d0{}, d1{}, d2{};
  for (std::size_t k = 0; k < t_.size(); ++k) {
    const double t = t_[k];
    const double x = (c[0] * t + c[1]) * t + c[2];
    const double root = std::sqrt(1.0 + x * x);
    const double s = 0.5 + x / (2.0 * root);
    const double ds = 1.0 / (2.0 * root * root * root);  // dS/dx
    xyz += weights_[k] * s;
    d0 += weights_[k] * (ds * t * t);
    d1 += weights_[k] * (ds * t);
    d2 += weights_[k] * ds;
  }
  jacobian = Mat3::from_columns(d0, d1, d2);
}

Vec3d JakobHanikaFitter::xyz(const NormalizedCoefficients& c) const {
  Vec3d out;
  Mat3 unused;
  evaluate(c, out, unused);
  return out;
}

JakobHanikaFitResult JakobHanikaFitter::fit(const Vec3d& target_xyz, const NormalizedCoefficients& initial,
                                            int max_iterations, double tolerance_delta_e) const {
  const Vec3d target_lab = xyz_to_lab(target_xyz, white_xyz_);
  JakobHanikaFitResult result;
  result.coefficients = initial;
  Vec3d xyz;
  Mat3 jacobian;
  evaluate(result.coefficients, xyz, jacobian);
  Vec3d residual = xyz_to_lab(xyz, white_xyz_) - target_lab;
  for (; result.iterations < max_iterations; ++result.iterations) {
    if (length(residual) < tolerance_delta_e) break;
    const Mat3 j = lab_jacobian(xyz, white_xyz_) * jacobian;
    const double det = determinant(j);
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) break;
    const Vec3d step = inverse(j) * residual;
    bool improved = false;
    for (double fraction = 1.0; fraction > 1e-4; fraction *= 0.5) {
      NormalizedCoefficients trial = result.coefficients;
      for (int i = 0; i < 3; ++i) trial[static_cast<std::size_t>(i)] -= fraction * step[static_cast<std::size_t>(i)];
      Vec3d trial_xyz;
      Mat3 trial_jacobian;
      evaluate(trial, trial_xyz, trial_jacobian);
      const Vec3d trial_residual = xyz_to_lab(trial_xyz, white_xyz_) - target_lab;
      if (length(trial_residual) < length(residual)) {
        result.coefficients = trial;
        xyz = trial_xyz;
        jacobian = trial_jacobian;
        residual = trial_residual;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  result.delta_e = length(residual);
  result.converged = result.delta_e < tolerance_delta_e;
  return result;
}

double jakob_hanika_scale(int k, int resolution) {
  auto smoothstep = [](double x) { return x * x * (3.0 - 2.0 * x); };
  return smoothstep(smoothstep(double(k) / (resolution - 1)));
}

Vec3d jakob_hanika_grid_rgb(int l, int k, int j, int i, int resolution) {
  const double z = jakob_hanika_scale(k, resolution);
  const double x = double(i) / (resolution - 1), y = double(j) / (resolution - 1);
  Vec3d rgb;
  rgb[static_cast<std::size_t>(l)] = z;
  rgb[static_cast<std::size_t>((l + 1) % 3)] = x * z;
  rgb[static_cast<std::size_t>((l + 2) % 3)] = y * z;
  return rgb;
}

JakobHanikaTableData generate_jakob_hanika_table(const Mat3& rgb_to_xyz, const DenseSpectrum& illuminant,
                                                 int resolution, JakobHanikaTableStats* stats) {
  const int res = resolution;
  const JakobHanikaFitter fitter(illuminant);
  JakobHanikaTableData table;
  table.resolution = res;
  for (int k = 0; k < res; ++k) table.scale.push_back(static_cast<float>(jakob_hanika_scale(k, res)));
  table.coefficients.assign(static_cast<std::size_t>(3) * res * res * res * 3, 0.0f);

  std::atomic<long> not_converged{0};
  std::mutex worst_mutex;
  double worst = 0.0;
  // One task per (l, j) row; along each grid column (fixed l, j, i) the fit walks z up from
  // k = res/5 and then down, each fit starting from its neighbour's solution (as the
  // paper's supplementary optimiser does): neighbouring colours have nearby coefficients,
  // so a few Gauss–Newton steps suffice and saturated colours are reached gradually.
  tbb::parallel_for(0, 3 * res, [&](int task) {
    const int l = task / res, j = task % res;
    double local_worst = 0.0;
    for (int i = 0; i < res; ++i) {
      const int start = res / 5;
      auto solve_from = [&](int k, NormalizedCoefficients& c) {
        const Vec3d rgb = jakob_hanika_grid_rgb(l, k, j, i, res);
        JakobHanikaFitResult r = fitter.fit(rgb_to_xyz * rgb, c);
        if (!r.converged) {
          // The warm start can come from an unreachable (out-of-locus) neighbour whose
          // coefficients saturate the sigmoid; restart from the flat grey of equal Y.
          const double y = std::clamp((rgb_to_xyz * rgb).y, 1e-6, 1.0 - 1e-6);
          const JakobHanikaFitResult cold = fitter.fit(rgb_to_xyz * rgb, {0.0, 0.0, SigmoidPolynomial::constant(y).c2});
          if (cold.delta_e < r.delta_e) r = cold;
        }
        c = r.coefficients;
        if (!r.converged) ++not_converged;
        local_worst = std::max(local_worst, r.delta_e);
        const SigmoidPolynomial nm = to_wavelength_nm(c);
        const std::size_t at = ((((static_cast<std::size_t>(l) * res + k) * res + j) * res) + i) * 3;
        table.coefficients[at + 0] = static_cast<float>(nm.c0);
        table.coefficients[at + 1] = static_cast<float>(nm.c1);
        table.coefficients[at + 2] = static_cast<float>(nm.c2);
      };
      NormalizedCoefficients c{0.0, 0.0, 0.0};
      for (int k = start; k < res; ++k) solve_from(k, c);
      c = {0.0, 0.0, 0.0};
      solve_from(start, c);
      for (int k = start - 1; k >= 0; --k) solve_from(k, c);
    }
    std::lock_guard lock(worst_mutex);
    worst = std::max(worst, local_worst);
  });
  if (stats) {
    stats->fits = 3L * res * res * res + 3L * res * res;
    stats->not_converged = not_converged;
    stats->max_delta_e = worst;
  }
  return table;
}

}  // namespace prism::color
