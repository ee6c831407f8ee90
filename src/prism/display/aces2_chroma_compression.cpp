#include "prism/display/aces2_chroma_compression.h"

#include <algorithm>
#include <cmath>

#include "prism/display/hellwig_cam.h"

namespace prism::display {
namespace {

// The toe of the technical details ("https://www.desmos.com/calculator/6vplvw14ti"):
// maps [0, limit] onto itself, k1 and k2 setting its size and shape; x > limit unchanged.
struct Toe {
  double limit, k1, k2, k3;
  Toe(double limit_in, double k1_in, double k2_in) : limit(limit_in) {
    k2 = std::max(k2_in, 0.001);
    k1 = std::sqrt(k1_in * k1_in + k2 * k2);
    k3 = (limit + k1) / (limit + k2);
  }
  double forward(double x) const {
    if (x > limit) return x;
    const double minus_b = k3 * x - k1;
    const double minus_c = k2 * k3 * x;
    return 0.5 * (minus_b + std::sqrt(minus_b * minus_b + 4.0 * minus_c));
  }
  double inverse(double x) const {
    if (x > limit) return x;
    return (x * x + k1 * x) / (k3 * (x + k2));
  }
};

constexpr double kChromaCompress = 2.4, kChromaCompressFact = 3.3;
constexpr double kChromaExpand = 1.3, kChromaExpandFact = 0.69, kChromaExpandThreshold = 0.5;

}  // namespace

Aces2ChromaCompression::Aces2ChromaCompression(double peak_luminance_nits) {
  const double log_peak = std::log10(peak_luminance_nits / 100.0);
  compression_ = kChromaCompress + kChromaCompress * kChromaCompressFact * log_peak;
  saturation_ = std::max(0.2, kChromaExpand - kChromaExpand * kChromaExpandFact * log_peak);
  saturation_threshold_ = kChromaExpandThreshold / peak_luminance_nits;
  scale_ = std::pow(0.03379 * peak_luminance_nits, 0.30596) - 0.45135;
}

double Aces2ChromaCompression::normaliser(double c1, double s1) const {
  const double c2 = 2.0 * c1 * c1 - 1.0, s2 = 2.0 * c1 * s1;
  const double c3 = 4.0 * c1 * c1 * c1 - 3.0 * c1, s3 = 3.0 * s1 - 4.0 * s1 * s1 * s1;
  const double m = 11.34072 * c1 + 16.46899 * c2 + 7.88380 * c3 + 14.66441 * s1 - 6.37224 * s2 +
                   9.19364 * s3 + 77.12896;
  return m * scale_;
}

double Aces2ChromaCompression::forward(double J, double M, double j_ts, const Context& c) const {
  if (M == 0.0) return M;
  const double gamma_inv = 1.0 / HellwigCam::model_gamma();
  const double nj = j_ts / c.limit_j_max;
  const double snj = std::max(0.0, 1.0 - nj);
  const double limit = std::pow(nj, gamma_inv) * c.reach_max_m / c.normaliser;
  const Toe expand(limit - 0.001, snj * saturation_, std::sqrt(nj * nj + saturation_threshold_));
  const Toe compress(limit, nj * compression_, snj);
  double m = M * std::pow(j_ts / J, gamma_inv) / c.normaliser;
  m = limit - expand.forward(limit - m);
  m = compress.forward(m);
  return m * c.normaliser;
}

double Aces2ChromaCompression::inverse(double J, double M_compressed, double j_ts, const Context& c) const {
  if (M_compressed == 0.0) return M_compressed;
  const double gamma_inv = 1.0 / HellwigCam::model_gamma();
  const double nj = j_ts / c.limit_j_max;
  const double snj = std::max(0.0, 1.0 - nj);
  const double limit = std::pow(nj, gamma_inv) * c.reach_max_m / c.normaliser;
  const Toe expand(limit - 0.001, snj * saturation_, std::sqrt(nj * nj + saturation_threshold_));
  const Toe compress(limit, nj * compression_, snj);
  double m = M_compressed / c.normaliser;
  m = compress.inverse(m);
  m = limit - expand.inverse(limit - m);
  return m * c.normaliser * std::pow(j_ts / J, -gamma_inv);
}

}  // namespace prism::display
