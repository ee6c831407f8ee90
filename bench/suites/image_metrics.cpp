#include "image_metrics.h"

#include <algorithm>
#include <cmath>

#include "prism/color/chromatic_adaptation.h"

namespace prism::bench {

std::vector<Vec3d> film_xyz(const Film& film, const color::ColorSpace& film_space) {
  std::vector<Vec3d> out(film.pixel_count());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = film_space.rgb_to_xyz * film.mean(i);
  return out;
}

std::vector<Vec3d> film_linear_srgb(const Film& film, const color::ColorSpace& film_space) {
  const Mat3 m = color::conversion_matrix(film_space, color::color_space("srgb"));
  std::vector<Vec3d> out(film.pixel_count());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = m * film.mean(i);
  return out;
}

std::vector<char> mask_without_lights(const std::vector<Vec3d>& reference_xyz) {
  double max_y = 0.0;
  for (const auto& v : reference_xyz) max_y = std::max(max_y, v.y);
  std::vector<char> mask(reference_xyz.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = reference_xyz[i].y <= 0.5 * max_y;
  return mask;
}

double relative_mse(const std::vector<Vec3d>& image, const std::vector<Vec3d>& reference,
                    const std::vector<char>& mask) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.size() && i < reference.size(); ++i) {
    if (!mask[i]) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = image[i][c] - reference[i][c];
      sum += d * d / (reference[i][c] * reference[i][c] + 0.01);
    }
    n += 3;
  }
  return n ? sum / static_cast<double>(n) : 0.0;
}

color::Chromaticity chromaticity_of(const Vec3d& xyz) {
  const double s = xyz.x + xyz.y + xyz.z;
  if (!(s > 0.0)) return {1.0 / 3, 1.0 / 3};
  return {xyz.x / s, xyz.y / s};
}

ChromaticityError chromaticity_error(const std::vector<Vec3d>& xyz, const std::vector<Vec3d>& reference_xyz,
                                     int width, int height, const Region& r) {
  const int x0 = static_cast<int>(r.x0 * width), x1 = std::max(x0 + 1, static_cast<int>(r.x1 * width));
  const int y0 = static_cast<int>(r.y0 * height), y1 = std::max(y0 + 1, static_cast<int>(r.y1 * height));
  Vec3d sum{0, 0, 0}, ref_sum{0, 0, 0};
  double per_pixel = 0.0;
  int n = 0;
  const auto distance = [](color::Chromaticity a, color::Chromaticity b) { return std::hypot(a.x - b.x, a.y - b.y); };
  for (int y = y0; y < y1 && y < height; ++y)
    for (int x = x0; x < x1 && x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      sum += xyz[i];
      ref_sum += reference_xyz[i];
      per_pixel += distance(chromaticity_of(xyz[i]), chromaticity_of(reference_xyz[i]));
      ++n;
    }
  ChromaticityError e;
  e.of_region_mean = distance(chromaticity_of(sum), chromaticity_of(ref_sum));
  e.per_pixel_mean = n ? per_pixel / n : 0.0;
  return e;
}

}  // namespace prism::bench
