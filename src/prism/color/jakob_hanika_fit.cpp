// Gauss–Newton fit of sigmoid-polynomial spectra in CIELAB (Jakob & Hanika 2019, §4) and
// the coefficient-table generator.
#include "prism/color/jakob_hanika_fit.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <tbb/parallel_for.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/cielab.h"
#include "prism/color/illuminants.h"

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

namespace {
double smoothstep(double x) { return x * x * (3.0 - 2.0 * x); }
}  // namespace

double jakob_hanika_scale(int k, int resolution) { return smoothstep(double(k) / (resolution - 1)); }

double jakob_hanika_chroma_node(int i, int resolution) { return smoothstep(double(i) / (resolution - 1)); }

Vec3d jakob_hanika_grid_rgb(int l, int k, int j, int i, int resolution) {
  const double z = jakob_hanika_scale(k, resolution);
  const double x = jakob_hanika_chroma_node(i, resolution), y = jakob_hanika_chroma_node(j, resolution);
  Vec3d rgb;
  rgb[static_cast<std::size_t>(l)] = z;
  rgb[static_cast<std::size_t>((l + 1) % 3)] = x * z;
  rgb[static_cast<std::size_t>((l + 2) % 3)] = y * z;
  return rgb;
}

namespace {

// One fit per grid node: Gauss–Newton from each seed in turn until one converges, then
// (if `cold_start`) from the flat grey of equal Y.
struct NodeFitter {
  const JakobHanikaFitter& fitter;
  const Mat3& rgb_to_xyz;
  int res;

  JakobHanikaFitResult fit(int l, int k, int j, int i, std::initializer_list<NormalizedCoefficients> seeds,
                           bool cold_start) const {
    const Vec3d xyz = rgb_to_xyz * jakob_hanika_grid_rgb(l, k, j, i, res);
    JakobHanikaFitResult best;
    best.delta_e = INFINITY;
    for (const NormalizedCoefficients& seed : seeds) {
      const JakobHanikaFitResult r = fitter.fit(xyz, seed);
      if (r.delta_e < best.delta_e) best = r;
      if (best.converged) return best;
    }
    if (!cold_start) return best;
    const double y = std::clamp(xyz.y, 1e-6, 1.0 - 1e-6);
    const JakobHanikaFitResult cold = fitter.fit(xyz, {0.0, 0.0, SigmoidPolynomial::constant(y).c2});
    if (cold.delta_e < best.delta_e) best = cold;
    return best;
  }
};

}  // namespace

JakobHanikaTableData generate_jakob_hanika_table(const Mat3& rgb_to_xyz, const DenseSpectrum& illuminant,
                                                 int resolution, JakobHanikaTableStats* stats) {
  const int res = resolution;
  const JakobHanikaFitter fitter(illuminant);
  const NodeFitter nodes{fitter, rgb_to_xyz, res};
  JakobHanikaTableData table;
  table.resolution = res;
  for (int k = 0; k < res; ++k) table.scale.push_back(static_cast<float>(jakob_hanika_scale(k, res)));

  const std::size_t count = static_cast<std::size_t>(3) * res * res * res;
  std::vector<JakobHanikaFitResult> fits(count);
  auto at = [&](int l, int k, int j, int i) -> JakobHanikaFitResult& {
    return fits[(((static_cast<std::size_t>(l) * res + k) * res + j) * res) + i];
  };

  // Continuation (Jakob & Hanika 2019, §4: each fit starts from a neighbour's solution), so
  // that neighbouring nodes hold solutions on the same branch:
  // 1. in the slice z = scale[k0] (k0 = res/5, as in the paper's optimiser) walk outwards
  //    from the grey node (x = y = 1: i = j = res − 1) along anti-diagonals, seeding each
  //    node from its already fitted neighbours towards grey;
  // 2. from that slice walk each column (fixed l, j, i) up and down in brightness, each fit
  //    seeded from the previous one.
  // (Step 1 replaced a cold start per column; on its own it changed no measured round-trip
  // error — the columns already shared branches. The errors came from the next point.)
  // Colours outside the optimal-colour solid (the reflectances' gamut under the illuminant;
  // the wide-gamut cubes reach past it near their faces and at bright saturated colours)
  // have no sigmoid spectrum: Gauss–Newton then drives the coefficients towards a step
  // function and stops anywhere (we measured |c| up to 1e15). Such a node only matters as
  // a corner of cells whose reachable part it would poison (a 1 % trilinear weight on
  // 1e4 outweighs everything else), so it stores the coefficients of the node it was
  // reached from instead: bounded, and equal to a reachable neighbour's.
  const int k0 = res / 5;
  tbb::parallel_for(0, 3, [&](int l) {
    for (int d = 0; d <= 2 * (res - 1); ++d)
      for (int j = std::max(0, res - 1 - d); j < res && res - 1 - j <= d; ++j) {
        const int i = res - 1 - (d - (res - 1 - j));
        if (i < 0) continue;
        const NormalizedCoefficients flat{0.0, 0.0, 0.0};
        const NormalizedCoefficients& from_i = i + 1 < res ? at(l, k0, j, i + 1).coefficients : flat;
        const NormalizedCoefficients& from_j = j + 1 < res ? at(l, k0, j + 1, i).coefficients : flat;
        NormalizedCoefficients mean;
        for (std::size_t n = 0; n < 3; ++n) mean[n] = 0.5 * (from_i[n] + from_j[n]);
        JakobHanikaFitResult& node = at(l, k0, j, i);
        node = nodes.fit(l, k0, j, i, {mean, from_i, from_j}, true);
        if (!node.converged) node.coefficients = mean;
      }
  });
  auto step = [&](int l, int k, int j, int i, int from_k) {
    const JakobHanikaFitResult& from = at(l, from_k, j, i);
    JakobHanikaFitResult node = nodes.fit(l, k, j, i, {from.coefficients}, from.converged);
    if (!node.converged) node.coefficients = from.coefficients;
    return node;
  };
  tbb::parallel_for(0, 3 * res, [&](int task) {
    const int l = task / res, j = task % res;
    for (int i = 0; i < res; ++i) {
      for (int k = k0 + 1; k < res; ++k) at(l, k, j, i) = step(l, k, j, i, k - 1);
      for (int k = k0 - 1; k >= 0; --k) at(l, k, j, i) = step(l, k, j, i, k + 1);
    }
  });

  table.coefficients.resize(count * 3);
  long not_converged = 0;
  double worst = 0.0;
  for (std::size_t n = 0; n < count; ++n) {
    const SigmoidPolynomial nm = to_wavelength_nm(fits[n].coefficients);
    table.coefficients[3 * n + 0] = static_cast<float>(nm.c0);
    table.coefficients[3 * n + 1] = static_cast<float>(nm.c1);
    table.coefficients[3 * n + 2] = static_cast<float>(nm.c2);
    if (!fits[n].converged) ++not_converged;
    worst = std::max(worst, fits[n].delta_e);
  }
  if (stats) {
    stats->fits = static_cast<long>(count);
    stats->not_converged = not_converged;
    stats->max_delta_e = worst;
  }
  return table;
}

Mat3 jakob_hanika_target_xyz_matrix(const ColorSpace& space) {
  return adaptation_matrix(white_XYZ(space), xy_to_XYZ(kWhiteE), Cat::bradford) * space.rgb_to_xyz;
}

JakobHanikaTableData generate_jakob_hanika_table(const ColorSpace& space, int resolution, JakobHanikaTableStats* stats) {
  return generate_jakob_hanika_table(jakob_hanika_target_xyz_matrix(space), standard_illuminant(StandardIlluminant::e),
                                     resolution, stats);
}

}  // namespace prism::color
