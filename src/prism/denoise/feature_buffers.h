#pragma once
// What the denoiser reads: the noisy beauty and the guides a renderer writes beside it
// (render/aov.h), as interleaved float arrays, row-major from the top-left
// pixel. The beauty is scene-linear radiance in one RGB space; albedo and variance are in
// the same space, so that demodulating by the albedo and scaling the variance by it are
// consistent.
#include <string>
#include <vector>

#include "prism/io/image.h"
#include "prism/core/mat3.h"
#include "prism/render/aov_images.h"
#include "prism/render/film.h"

namespace prism::denoise {

struct DenoiseBuffers {
  int width = 0, height = 0;
  std::vector<float> color;     // 3 per pixel: the noisy pixel means
  std::vector<float> variance;  // 3 per pixel: variance of each pixel mean (s² / n), ≥ 0
  std::vector<float> albedo;    // 3 per pixel: first-hit reflectance (0 on a miss)
  std::vector<float> normal;    // 3 per pixel: first-hit shading normal (0 on a miss)
  std::vector<float> depth;     // 1 per pixel: distance to the first hit; +inf or 0 on a miss

  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }
};

// The names of the AOVs an AovSet lacks for denoising ("albedo", "normal", "depth",
// "variance"), in that order; empty when everything is there.
std::vector<std::string> missing_denoise_aovs(const AovSet& set);

// The beauty and a render's AOV images (all four of albedo, normal, depth, variance, in the
// beauty's colour space) as denoiser input. Throws Error when an AOV is missing or a size
// differs.
DenoiseBuffers denoise_buffers(const ImageRgbF& beauty, const AovImages& aovs);

// A film's beauty and AOVs converted to one RGB space by `film_to_output` (the film must
// hold all four AOVs). Throws Error naming the missing AOVs otherwise.
DenoiseBuffers film_denoise_buffers(const Film& film, const Mat3& film_to_output);

// Throws Error unless every array has the size width × height asks for.
void check_denoise_buffers(const DenoiseBuffers& buffers);

}  // namespace prism::denoise
