#include "prism/denoise/demodulation.h"

#include <algorithm>
#include <cmath>

namespace prism::denoise {

std::vector<float> demodulation_divisors(const std::vector<float>& albedo) {
  std::vector<float> d(albedo.size(), 1.0f);
  for (std::size_t i = 0; i + 2 < albedo.size(); i += 3) {
    const float a[3] = {albedo[i], albedo[i + 1], albedo[i + 2]};
    bool finite = true;
    for (float v : a) finite = finite && std::isfinite(v);
    if (!finite || std::max({a[0], a[1], a[2]}) < kAlbedoFloor) continue;  // a miss or black: keep 1
    for (int c = 0; c < 3; ++c) d[i + c] = std::max(a[c], kAlbedoFloor);
  }
  return d;
}

}  // namespace prism::denoise
