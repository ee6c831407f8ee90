#include "support/chi_square.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "prism/core/pcg32.h"

namespace prism::test {
namespace {

// Regularised lower incomplete gamma P(a, x) by its power series (converges for x < a+1).
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Regularised upper incomplete gamma Q(a, x) by Lentz's continued fraction (x >= a+1).
double gamma_q_continued_fraction(double a, double x) {
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chi_square_survival(double x, int dof) {
  if (x <= 0.0) return 1.0;
  const double a = 0.5 * dof, half_x = 0.5 * x;
  return half_x < a + 1.0 ? 1.0 - gamma_p_series(a, half_x) : gamma_q_continued_fraction(a, half_x);
}

double sidak_alpha(double alpha_total, int test_count) {
  return 1.0 - std::pow(1.0 - alpha_total, 1.0 / test_count);
}

ChiSquareResult chi_square_test(std::span<const double> observed, std::span<const double> expected,
                                double min_expected) {
  ChiSquareResult result;
  std::vector<std::size_t> order(expected.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return expected[a] < expected[b]; });

  double pooled_observed = 0.0, pooled_expected = 0.0;
  int bins = 0;
  for (std::size_t i : order) {
    if (expected[i] <= 1e-12 * (1.0 + observed[i])) {
      if (observed[i] > 0.0) {
        std::ostringstream os;
        os << "bin " << i << " has " << observed[i] << " samples but zero expected mass";
        result.message = os.str();
        result.p_value = 0.0;
        return result;
      }
      continue;
    }
    if (expected[i] < min_expected) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      if (pooled_expected >= min_expected) {
        result.statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
        ++bins;
        pooled_observed = pooled_expected = 0.0;
      }
      continue;
    }
    const double diff = observed[i] - expected[i];
    result.statistic += diff * diff / expected[i];
    ++bins;
  }
  if (pooled_expected > 0.0) {
    // Leftover sparse mass: fold it into the statistic as one more (small) bin.
    result.statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++bins;
  }
  result.degrees_of_freedom = std::max(1, bins - 1);
  result.p_value = chi_square_survival(result.statistic, result.degrees_of_freedom);
  std::ostringstream os;
  os << "chi2 = " << result.statistic << ", dof = " << result.degrees_of_freedom
     << ", p = " << result.p_value;
  result.message = os.str();
  return result;
}

SphericalHistogram spherical_histogram(const std::function<bool(Vec2f, Vec3f&)>& sample,
                                       const std::function<double(const Vec3f&)>& pdf,
                                       int cos_theta_bins, int phi_bins, long sample_count,
                                       unsigned long long seed, int simpson_intervals) {
  constexpr double kTwoPi = 6.283185307179586;
  SphericalHistogram h;
  h.observed.assign(static_cast<std::size_t>(cos_theta_bins * phi_bins), 0.0);
  h.expected.assign(h.observed.size(), 0.0);

  Pcg32 rng(seed, 7);
  for (long i = 0; i < sample_count; ++i) {
    Vec3f d;
    if (!sample(Vec2f(rng.next_float(), rng.next_float()), d)) continue;
    const double cos_theta = std::clamp(static_cast<double>(d.z), -1.0, 1.0);
    double phi = std::atan2(static_cast<double>(d.y), static_cast<double>(d.x));
    if (phi < 0.0) phi += kTwoPi;
    const int ci = std::min(cos_theta_bins - 1, static_cast<int>((cos_theta + 1.0) * 0.5 * cos_theta_bins));
    const int pi = std::min(phi_bins - 1, static_cast<int>(phi / kTwoPi * phi_bins));
    h.observed[static_cast<std::size_t>(ci * phi_bins + pi)] += 1.0;
  }

  // Integrate the pdf over each bin with a 2D Simpson rule in (cos θ, φ); the solid-angle
  // measure is exactly d(cos θ) dφ, so no Jacobian is needed.
  const int kSub = simpson_intervals + simpson_intervals % 2;  // per bin and axis (even)
  const double dc = 2.0 / cos_theta_bins, dp = kTwoPi / phi_bins;
  for (int ci = 0; ci < cos_theta_bins; ++ci) {
    for (int pi = 0; pi < phi_bins; ++pi) {
      double integral = 0.0;
      for (int a = 0; a <= kSub; ++a) {
        const double wa = (a == 0 || a == kSub) ? 1.0 : (a % 2 ? 4.0 : 2.0);
        const double c = -1.0 + dc * (ci + static_cast<double>(a) / kSub);
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        for (int b = 0; b <= kSub; ++b) {
          const double wb = (b == 0 || b == kSub) ? 1.0 : (b % 2 ? 4.0 : 2.0);
          const double p = dp * (pi + static_cast<double>(b) / kSub);
          const Vec3f d(static_cast<float>(s * std::cos(p)), static_cast<float>(s * std::sin(p)),
                        static_cast<float>(c));
          integral += wa * wb * pdf(d);
        }
      }
      integral *= (dc / kSub / 3.0) * (dp / kSub / 3.0);
      h.expected[static_cast<std::size_t>(ci * phi_bins + pi)] = integral * sample_count;
    }
  }
  return h;
}

}  // namespace prism::test
