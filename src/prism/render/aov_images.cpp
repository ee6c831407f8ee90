#include "prism/render/aov_images.h"

namespace prism {

AovImages film_aov_images(const Film& film, const Mat3& film_to_output) {
  AovImages out;
  out.set = film.aovs();
  const std::size_t n = film.pixel_count();
  const auto rgb_image = [&] { return ImageRgbF{film.width(), film.height(), std::vector<float>(3 * n)}; };
  if (out.set.albedo) out.albedo = rgb_image();
  if (out.set.normal) out.normal = rgb_image();
  if (out.set.variance) out.variance = rgb_image();
  if (out.set.sample_count) out.sample_count.resize(n);
  if (out.set.depth) {
    out.depth.resize(n);
    out.depth_coverage.resize(n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (out.set.albedo) {
      const Vec3d a = film_to_output * film.albedo_mean(i);
      for (int c = 0; c < 3; ++c) out.albedo.rgb[3 * i + c] = static_cast<float>(a[c]);
    }
    if (out.set.normal) {
      const Vec3d v = film.normal_mean(i);
      for (int c = 0; c < 3; ++c) out.normal.rgb[3 * i + c] = static_cast<float>(v[c]);
    }
    if (out.set.variance) {
      const Vec3d v = film.variance_of_mean(i, film_to_output);
      for (int c = 0; c < 3; ++c) out.variance.rgb[3 * i + c] = static_cast<float>(v[c]);
    }
    if (out.set.sample_count) out.sample_count[i] = static_cast<float>(film.sample_count(i));
    if (out.set.depth) {
      out.depth[i] = static_cast<float>(film.depth_mean(i));
      out.depth_coverage[i] = static_cast<float>(film.depth_coverage(i));
    }
  }
  return out;
}

}  // namespace prism
