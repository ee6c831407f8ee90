#include "render_denoise.h"

#include "denoise_exr.h"
#include "prism/color/chromatic_adaptation.h"
#include "prism/denoise/denoiser.h"

namespace prism::cli {

void add_denoise_aovs(AovSet& aovs) {
  aovs.albedo = true;
  aovs.normal = true;
  aovs.depth = true;
  aovs.variance = true;
}

ImageRgbF denoise_film(const Film& film, const color::ColorSpace& film_space, const color::ColorSpace& working) {
  const Mat3 to_working = color::conversion_matrix(film_space, working);
  return denoise::denoise_image(denoise::film_denoise_buffers(film, to_working));
}

ImageRgbF convert_image(const ImageRgbF& image, const color::ColorSpace& from, const color::ColorSpace& to) {
  if (from.name == to.name) return image;
  const Mat3 m = color::conversion_matrix(from, to);
  ImageRgbF out = image;
  for (std::size_t i = 0; 3 * i + 2 < out.rgb.size(); ++i) {
    const Vec3d v = m * Vec3d(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]);
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = static_cast<float>(v[c]);
  }
  return out;
}

ImageRgbF exr_denoised_beauty(const ImageRgbF& noisy, const ImageRgbF& denoised, const color::ColorSpace& working,
                              const color::ColorSpace& space, std::vector<ExrChannelGroup>& layers) {
  layers.insert(layers.begin(), noisy_beauty_channels(noisy.rgb));
  return convert_image(denoised, working, space);
}

}  // namespace prism::cli
