#pragma once
// A film's AOVs (aov.h) as per-pixel means in single precision, the form that is written
// to files and merged (`prism merge`), row-major from the top-left pixel.
#include <vector>

#include "prism/core/mat3.h"
#include "prism/io/image.h"
#include "prism/render/film.h"

namespace prism {

struct AovImages {
  AovSet set;
  ImageRgbF albedo;                    // in the output colour space (converted like the beauty)
  ImageRgbF normal;                    // world-space x, y, z
  std::vector<float> depth;            // scene units; +inf where no sample hit a surface
  std::vector<float> depth_coverage;   // fraction of samples that hit (what depth averages over)
  ImageRgbF variance;                  // of the beauty's pixel mean, per output channel
  std::vector<float> sample_count;     // samples in the pixel's mean (exact below 2^24)
};

// `film_to_output` converts the film's colour space to the output's (the albedo's only
// colour transform, and the one the variance is taken through; identity keeps film values).
AovImages film_aov_images(const Film& film, const Mat3& film_to_output);

}  // namespace prism
