#pragma once
// `prism render --denoise`: the film denoised in the working space (scene-linear, before the
// display pipeline), and the EXR layout that keeps the noisy beauty beside it.
#include <vector>

#include "prism/color/color_space.h"
#include "prism/io/exr.h"
#include "prism/render/aov.h"
#include "prism/render/film.h"

namespace prism::cli {

// The AOVs the denoiser reads: albedo, normal, depth and variance.
void add_denoise_aovs(AovSet& aovs);

// The film's beauty denoised, in `working` RGB.
ImageRgbF denoise_film(const Film& film, const color::ColorSpace& film_space, const color::ColorSpace& working);

// `image` (in `from`) converted to `to` (one 3×3 with Bradford adaptation between whites).
ImageRgbF convert_image(const ImageRgbF& image, const color::ColorSpace& from, const color::ColorSpace& to);

// For an EXR in `space`: appends noisy.R/G/B (the film's beauty, `noisy`) to `layers` and
// returns the denoised beauty (`denoised`, in `working`) converted to `space`.
ImageRgbF exr_denoised_beauty(const ImageRgbF& noisy, const ImageRgbF& denoised, const color::ColorSpace& working,
                              const color::ColorSpace& space, std::vector<ExrChannelGroup>& layers);

}  // namespace prism::cli
