#pragma once
// Adaptive sampling (`prism render --noise-threshold T`): a pixel stops taking samples once
// the estimated relative standard error of its mean luminance falls below T. Background:
// Cycles' "Adaptive Sampling" (Blender manual, Render › Cycles › Sampling: noise threshold,
// min samples) and the per-pixel error estimates of Rousselle, Knaus, Zwicker 2011
// ("Adaptive sampling and reconstruction using greedy error minimization"); the rule here
// is the plain one below, on the film's own sums.
//
// The rule, at a decision boundary b (b = N_min, 2·N_min, 3·N_min, … below the --spp cap),
// for each pixel with n = b samples:
//   Y_i     luminance of sample i: the Y row of the film space's RGB→XYZ matrix applied to
//           the film-space sample (working RGB, or XYZ relative to E for spectral films)
//   Var[Ȳ]  = ℓᵀ C ℓ / n, C the pixel's sample covariance of the three channels (the film's
//           squares and cross sums, Film::variance_of_mean), ℓ the luminance row
//   floor   = kDarkFloorFraction × the image's mean luminance at b (mean over pixels of Ȳ)
//   error   = sqrt(Var[Ȳ]) / max(|Ȳ|, floor); 0 where Var[Ȳ] = 0 (a flat or black pixel)
//   the pixel goes on taking samples after b iff error > T.
// The floor keeps dark pixels from sampling to the cap: their relative error divides by a
// tiny mean, yet on a display their noise is measured against the image's brightness
// (sRGB and the tone curves map equal steps of relative luminance to about equal steps of
// code value, down to a few percent of the scene's mid grey, below which steps vanish into
// black); a tenth of the image mean sits a little above that.
//
// Determinism. Which pixels render the samples of a pass is a pure function of the film at
// the pass's first sample index s (adaptive_active_pixels): before N_min every pixel; at a
// boundary, the pixels that took every sample so far (count == s) and are not converged;
// between boundaries, the pixels that took every sample so far. The render loop clips its
// passes so that none straddles a boundary (next_adaptive_boundary), every pixel's samples
// depend only on (seed, pixel, sample index), and a checkpoint holds the film and the next
// sample index, so the image is bitwise the same for any thread count, any pass grouping,
// time limit or resume. A pixel one of whose samples was discarded as NaN/Inf (the render
// reports how many) has count < s and stops at the next pass: the rule needs no state
// beyond the film, at the price of treating such a pixel as converged.
#include <cstdint>
#include <optional>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/render/aov.h"
#include "prism/render/film.h"

namespace prism {

struct AdaptiveSamplingSettings {
  double noise_threshold = 0.0;  // T; 0: off (every pixel takes every sample)
  // N_min: samples before the first decision, and the spacing of later decisions.
  int min_samples = 16;
  // The one-pixel dilation of the mask (see the rule above); off only to measure what it
  // costs (`prism bench adaptive`): the command line always has it on.
  bool dilate = true;
  bool enabled() const { return noise_threshold > 0.0; }
};

// The floor's fraction of the image's mean luminance (see the rule above).
inline constexpr double kDarkFloorFraction = 0.1;

// Throws UsageError naming the option for a negative or non-finite threshold, or
// min samples below 2 (a variance needs two samples).
void validate_adaptive_sampling(const AdaptiveSamplingSettings& settings);

// The film AOVs an adaptive render keeps: the requested ones plus the variance AOV's cross
// sums, which Var[Ȳ] needs (the film's squares alone give per-channel variances, and the
// luminance mixes correlated channels).
AovSet adaptive_film_aovs(const AovSet& requested, const AdaptiveSamplingSettings& settings);

// The first decision boundary after `sample` (the next multiple of N_min), or `cap` when
// none lies below it; `cap` when adaptive sampling is off.
int next_adaptive_boundary(const AdaptiveSamplingSettings& settings, int sample, int cap);

// Relative standard error of pixel's mean luminance (the rule's `error`), for a given floor.
double relative_luminance_error(const Film& film, std::size_t pixel, const Vec3d& luminance_row, double floor);

// The image's mean luminance (mean over pixels with samples of their Ȳ), summed in pixel
// order so that it is the same bits for any thread count.
double mean_image_luminance(const Film& film, const Vec3d& luminance_row);

// Which pixels render samples next_sample … of the next pass (1: render, 0: skip), or
// nullopt where every pixel does (adaptive sampling off, or before N_min). `film_space`:
// the film's colour space (RenderResult::film_space), whose RGB→XYZ gives the luminance row.
std::optional<std::vector<std::uint8_t>> adaptive_active_pixels(const Film& film, const color::ColorSpace& film_space,
                                                                const AdaptiveSamplingSettings& settings,
                                                                int next_sample);

}  // namespace prism
