#include "prism/scene/environment_lookup.h"

#include <algorithm>
#include <cmath>

namespace prism {

std::pair<int, int> environment_texel_address(EnvironmentMapping mapping, int x, int y, int width, int height) {
  if (mapping == EnvironmentMapping::equirectangular) {
    x %= width;
    if (x < 0) x += width;
    return {x, std::clamp(y, 0, height - 1)};
  }
  // The folds in x, then in y: a corner's diagonal neighbour is the opposite corner.
  if (x < 0) {
    x = -x - 1;
    y = height - 1 - y;
  } else if (x >= width) {
    x = 2 * width - 1 - x;
    y = height - 1 - y;
  }
  if (y < 0) {
    y = -y - 1;
    x = width - 1 - x;
  } else if (y >= height) {
    y = 2 * height - 1 - y;
    x = width - 1 - x;
  }
  return {std::clamp(x, 0, width - 1), std::clamp(y, 0, height - 1)};
}

Vec3f environment_radiance_bilinear(const TextureImage& map, EnvironmentMapping mapping, Vec2f uv) {
  // Texel-centre coordinates; uv a rounding error outside [0,1] (or NaN) is taken as the
  // nearest border.
  const float s = std::fmin(std::fmax(uv.x * map.width - 0.5f, -0.5f), map.width - 0.5f);
  const float t = std::fmin(std::fmax(uv.y * map.height - 0.5f, -0.5f), map.height - 0.5f);
  const float s0 = std::floor(s), t0 = std::floor(t);
  const float fs = s - s0, ft = t - t0;
  const int x0 = static_cast<int>(s0), y0 = static_cast<int>(t0);
  const auto at = [&](int x, int y) {
    const auto [ax, ay] = environment_texel_address(mapping, x, y, map.width, map.height);
    return texel_rgb(map, ax, ay);
  };
  return (at(x0, y0) * (1.0f - fs) + at(x0 + 1, y0) * fs) * (1.0f - ft) +
         (at(x0, y0 + 1) * (1.0f - fs) + at(x0 + 1, y0 + 1) * fs) * ft;
}

double environment_texel_mean(std::span<const float> values, EnvironmentMapping mapping, int x, int y, int width,
                              int height) {
  constexpr double kWeight[3] = {0.125, 0.75, 0.125};
  double mean = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const auto [ax, ay] = environment_texel_address(mapping, x + dx, y + dy, width, height);
      mean += kWeight[dx + 1] * kWeight[dy + 1] * values[static_cast<std::size_t>(ay) * width + ax];
    }
  return mean;
}

}  // namespace prism
