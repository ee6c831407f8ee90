#include "prism/denoise/feature_buffers.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"

namespace prism::denoise {

std::vector<std::string> missing_denoise_aovs(const AovSet& set) {
  std::vector<std::string> missing;
  if (!set.albedo) missing.emplace_back("albedo");
  if (!set.normal) missing.emplace_back("normal");
  if (!set.depth) missing.emplace_back("depth");
  if (!set.variance) missing.emplace_back("variance");
  return missing;
}

DenoiseBuffers denoise_buffers(const ImageRgbF& beauty, const AovImages& aovs) {
  const auto missing = missing_denoise_aovs(aovs.set);
  if (!missing.empty()) throw Error(fmt::format("denoising needs the AOVs {}", fmt::join(missing, ", ")));
  DenoiseBuffers b;
  b.width = beauty.width;
  b.height = beauty.height;
  b.color = beauty.rgb;
  b.variance = aovs.variance.rgb;
  b.albedo = aovs.albedo.rgb;
  b.normal = aovs.normal.rgb;
  b.depth = aovs.depth;
  check_denoise_buffers(b);
  return b;
}

DenoiseBuffers film_denoise_buffers(const Film& film, const Mat3& film_to_output) {
  const auto missing = missing_denoise_aovs(film.aovs());
  if (!missing.empty()) throw Error(fmt::format("denoising needs the AOVs {}", fmt::join(missing, ", ")));
  ImageRgbF beauty{film.width(), film.height(), std::vector<float>(3 * film.pixel_count())};
  for (std::size_t i = 0; i < film.pixel_count(); ++i) {
    const Vec3d v = film_to_output * film.mean(i);
    for (int c = 0; c < 3; ++c) beauty.rgb[3 * i + c] = static_cast<float>(v[c]);
  }
  return denoise_buffers(beauty, film_aov_images(film, film_to_output));
}

void check_denoise_buffers(const DenoiseBuffers& b) {
  if (b.width <= 0 || b.height <= 0) throw Error("denoising needs a non-empty image");
  const std::size_t n = b.pixel_count();
  const auto check = [&](const std::vector<float>& v, std::size_t per_pixel, const char* name) {
    if (v.size() != per_pixel * n)
      throw Error(fmt::format("denoiser input '{}' holds {} values, not {} for {}x{} pixels", name, v.size(),
                              per_pixel * n, b.width, b.height));
  };
  check(b.color, 3, "color");
  check(b.variance, 3, "variance");
  check(b.albedo, 3, "albedo");
  check(b.normal, 3, "normal");
  check(b.depth, 1, "depth");
}

}  // namespace prism::denoise
