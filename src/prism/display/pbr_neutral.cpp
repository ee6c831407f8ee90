#include "prism/display/pbr_neutral.h"

#include <algorithm>
#include <cmath>

namespace prism::display {

Vec3d pbr_neutral(const Vec3d& rec709_linear) {
  Vec3d c;
  for (int k = 0; k < 3; ++k) c[k] = std::isfinite(rec709_linear[k]) ? std::max(rec709_linear[k], 0.0) : 0.0;
  // Toe: subtract F90 above 2·F90, a quadratic that meets it with equal slope below (6.25 = 1/(4·F90)).
  const double x = std::min({c[0], c[1], c[2]});
  const double offset = x < 2.0 * kPbrNeutralF90 ? x - x * x / (4.0 * kPbrNeutralF90) : kPbrNeutralF90;
  for (int k = 0; k < 3; ++k) c[k] -= offset;
  const double peak = std::max({c[0], c[1], c[2]});
  if (peak < kPbrNeutralStartCompression) return c;
  // Shoulder: compress the peak toward 1, scale the colour with it, and blend toward white by
  // how much was compressed.
  const double d = 1.0 - kPbrNeutralStartCompression;
  const double new_peak = 1.0 - d * d / (peak + d - kPbrNeutralStartCompression);
  const double g = 1.0 - 1.0 / (kPbrNeutralDesaturation * (peak - new_peak) + 1.0);
  for (int k = 0; k < 3; ++k) c[k] = (1.0 - g) * c[k] * (new_peak / peak) + g * new_peak;
  return c;
}

}  // namespace prism::display
