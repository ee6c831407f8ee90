#pragma once
// Exposure metering: the EV100 a camera's meter would pick for a rendered film, one rule for
// `prism render`, `prism tonemap --auto-exposure` and the viewer (docs/display-pipeline.md,
// "Exposure metering").
//
//   1. Zones. The film is cut into square zones of s = max(1, ⌊min(W, H) / 32⌋) pixels a side
//      (32 zones across the short side, as a camera's multi-zone meter), and each zone's
//      luminance is the coverage-weighted mean Y_z = Σ c_i·Y_i / Σ c_i of its pixels, where
//      c_i ∈ [0, 1] is the fraction of the pixel's camera rays that hit a surface. Pixels
//      that see nothing (the void around a Cornell box, c = 0) do not count; NaN/Inf pixels
//      do not count. Averaging in linear light before the logarithm keeps the Monte Carlo
//      noise of a 1-spp film from biasing the log mean (E[log X] < log E[X]).
//   2. Histogram. A histogram of log2 Y_z with 64 bins per EV between the luminances that
//      EV100 = ev100_min − 1 and ev100_max + 1 would put at the key (values outside, black
//      included, fall into the end bins, so that they meter outside the clamp), each zone
//      weighted by Σ c_i times the centre weight of its centre,
//      w(r) = (1 − k) + k·exp(−r² / (2·0.4²)), r the distance from the image centre in
//      half-diagonals and k = centre_weight.
//   3. Trimmed mean. The mean of log2 Y over the histogram's weight between the
//      low_percentile and high_percentile quantiles (the darkest and brightest tails are
//      discarded: deep shadows, light sources, highlights; by default the darkest and
//      brightest tenths), as game engines' histogram auto exposure does (Unreal's Low/High
//      Percent, Unity HDRP's histogram percentages).
//   4. EV100 = log2(Y_m / (1.2·key)), so that the metered luminance Y_m exposes to `key`
//      (exposure.h: exposed = Y / (1.2·2^EV100)), clamped to [ev100_min, ev100_max] and
//      rounded to 1/100 EV, so that the printed value repeats the picture exactly.
// A film with no covered pixel (a frame of sky alone, or no coverage given) meters every
// finite pixel instead; a film with no light at all gets EV100 0.
#include <optional>
#include <string>
#include <vector>

#include "prism/core/vec.h"
#include "prism/io/image.h"

namespace prism::display {

struct MeteringSettings {
  // Quantiles of the zone weight kept by the trimmed mean: the darkest 10 % and the
  // brightest 10 % are discarded, so the window is centred on the median and the image's
  // median luminance lands near the key (ACES and the other renderings show scene 0.18 at
  // 10–20 % of SDR white). Wide rather than narrow: on a bimodal image (half in hard sun,
  // half in shadow) a narrow window sits on the boundary between the modes, where framing or
  // a 1-spp film's noise move the reading by a stop (measured: 40–60 % put render and view
  // of dispersion-prism 1.07 EV apart, 10–90 % 0.43 EV; docs/display-pipeline.md).
  double low_percentile = 0.10;
  double high_percentile = 0.90;
  double centre_weight = 0.0;  // k in [0, 1]; 0: every covered zone counts the same
  double key = 0.18;           // the exposed value the metered luminance maps to
  // Moonless night (about −6) to noon sun on snow (about 17) with a margin: beyond these a
  // scene in nits is implausible, and the clamp keeps a black or empty frame from a gain of
  // 2^30.
  double ev100_min = -10.0;
  double ev100_max = 20.0;
};

// Throws UsageError unless 0 ≤ low < high ≤ 1, k ∈ [0, 1], key > 0 and min < max (finite).
void validate_metering_settings(const MeteringSettings& settings);

struct MeteredExposure {
  double ev100 = 0.0;                 // clamped and rounded to 1/100
  double metered_luminance_nits = 0;  // Y_m, the trimmed mean's luminance (before the clamp)
  double covered_fraction = 0;        // Σ c_i / pixel count
  bool clamped = false;               // the clamp changed the EV
};

// Meters `film` (RGB in a space whose luminance is luminance_weights · rgb, in nits).
// `coverage`: one value per pixel in [0, 1] (the fraction of camera rays that hit a
// surface); empty: every pixel counts fully.
MeteredExposure meter_exposure(const ImageRgbF& film, const Vec3d& luminance_weights,
                               const std::vector<float>& coverage, const MeteringSettings& settings);

// The goal the metering is held to (docs/display-pipeline.md): the coverage-weighted median
// of the displayed relative luminance Y / Y_white of an SDR display image (`nits` in its
// output primaries, white at white_nits), over the pixels that see something. Coverage as
// for meter_exposure (empty: every pixel). A photograph's mid-tones: 0.05–0.30.
double median_displayed_luminance(const std::vector<float>& display_nits, const std::string& primaries,
                                  double white_nits, const std::vector<float>& coverage);

// Eye adaptation in log space: the shown EV moves toward the metered one exponentially,
// metered + (shown − metered)·exp(−speed·dt), so that the exposure glides instead of
// jumping when the view changes and does not flicker as samples accumulate. speed in 1/s
// (0: frozen; +inf: instant); no shown EV yet (the first frame): the metered one.
double adapt_ev100(std::optional<double> shown_ev100, double metered_ev100, double dt_seconds, double speed_per_second);

}  // namespace prism::display
