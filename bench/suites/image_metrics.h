#pragma once
// Error measures between a film and a reference film of the same scene, for the
// convergence and efficiency suites.
#include <vector>

#include "prism/color/chromaticity.h"
#include "prism/color/color_space.h"
#include "prism/render/film.h"

namespace prism::bench {

// The film's pixel means as CIE XYZ (through film_space.rgb_to_xyz; spectral films
// already hold XYZ).
std::vector<Vec3d> film_xyz(const Film& film, const color::ColorSpace& film_space);
// The film's pixel means in linear sRGB (Bradford from the film's white), as pbrt-v4
// writes its RGB film, so that relative MSE is computed on the same channels.
std::vector<Vec3d> film_linear_srgb(const Film& film, const color::ColorSpace& film_space);

// Pixels to score: all but those whose reference luminance exceeds half the brightest
// pixel's (the directly visible light, excluded as in the pbrt-v4 figure).
std::vector<char> mask_without_lights(const std::vector<Vec3d>& reference_xyz);

// Mean over scored pixels and channels of (x − r)² / (r² + 0.01): the relative MSE of
// pbrt-v4's image tools; ε keeps black pixels from dominating.
double relative_mse(const std::vector<Vec3d>& image, const std::vector<Vec3d>& reference,
                    const std::vector<char>& mask);

// Pixel rectangle [x0, x1) × [y0, y1) given as fractions of the image size.
struct Region {
  double x0, y0, x1, y1;
};
// The Cornell box's back wall above the blocks, below the light's glow: a white wall.
inline constexpr Region kBackWallRegion{0.40, 0.22, 0.60, 0.36};

struct ChromaticityError {
  double of_region_mean = 0;  // |xy(Σ XYZ) − xy(Σ XYZ_ref)| over the region
  double per_pixel_mean = 0;  // mean over the region's pixels of |xy − xy_ref|
};
ChromaticityError chromaticity_error(const std::vector<Vec3d>& xyz, const std::vector<Vec3d>& reference_xyz,
                                     int width, int height, const Region& region);

color::Chromaticity chromaticity_of(const Vec3d& xyz);

}  // namespace prism::bench
