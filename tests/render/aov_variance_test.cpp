// The variance AOV (aov.h): the variance of the beauty's pixel mean in the output colour
// space, exact through the film → output matrix, consistent across checkpoints (see
// checkpoint_test.cpp) and `prism merge`.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/render/aov_images.h"
#include "prism/render/color_context.h"
#include "prism/render/merge_partial_renders.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"

namespace prism {
namespace {

TEST(AovVariance, PixelWithKnownSamplesGivesTheOutputSpaceVarianceOfItsMean) {
  // Five known film-space samples, correlated across channels, through a real colour
  // conversion (ACEScg → sRGB, negative and off-diagonal entries). The reference is the
  // textbook estimate on the converted samples themselves: s²/n per output channel, in
  // double (agreement to 1e-12 relative: rounding only).
  const Vec3d samples[] = {{1.0, 0.5, 0.2}, {4.0, 3.0, 0.1}, {0.2, 0.1, 2.5}, {2.0, 2.2, 1.9}, {0.0, 0.3, 0.0}};
  const Mat3 to_output = color::conversion_matrix(color::color_space("acescg"), color::color_space("srgb"));
  Film film(2, 1, AovSet{false, false, false, true});
  for (const Vec3d& x : samples) film.add_sample(0, x);
  film.add_sample(1, Vec3d(3.0));  // one sample: no variance estimate, 0
  const double n = 5.0;
  Vec3d mean, expected, naive;
  for (const Vec3d& x : samples) mean += to_output * x / n;
  for (const Vec3d& x : samples) {
    const Vec3d d = to_output * x - mean;
    expected += d * d / ((n - 1.0) * n);
  }
  const Vec3d got = film.variance_of_mean(0, to_output);
  // What converting per-channel variances would give (wrong: ignores the covariances).
  const Vec3d per_channel = film.variance_of_mean(0);
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) naive[k] += to_output(k, c) * to_output(k, c) * per_channel[c];
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(got[k], expected[k], 1e-12 * expected[k]) << "channel " << k;
    EXPECT_GT(std::abs(naive[k] - expected[k]), 0.01 * expected[k]) << "the covariances matter here, channel " << k;
  }
  EXPECT_EQ(film.variance_of_mean(1, to_output), Vec3d(0.0));
  // Identity: the film's own per-channel estimate.
  const Vec3d own = film.variance_of_mean(0, Mat3::identity());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(own[k], per_channel[k], 1e-12 * per_channel[k]);
  const AovImages images = film_aov_images(film, to_output);
  ASSERT_EQ(images.variance.rgb.size(), 6u);
  for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(images.variance.rgb[static_cast<std::size_t>(k)], static_cast<float>(expected[k]));
}

TEST(AovVariance, MergedPartsGiveTheSingleRendersVariance) {
  // Samples [0, 3) and [3, 10) rendered apart and merged must give the variance the
  // uninterrupted 10-sample render computes (the sampler gives each sample the same
  // numbers in both). Float files and a float merged mean: 1e-4 relative (plus 1e-12
  // absolute for black pixels).
  const Scene scene = make_cornell_box();
  RenderSettings s;
  s.width = 24;
  s.height = 20;
  s.seed = 4;
  s.aovs.variance = true;
  const Mat3 to_output = color::conversion_matrix(film_color_space(s.transport), color::color_space("rec2020"));
  const auto part = [&](int begin, int end) {
    RenderSettings p = s;
    p.first_sample = begin;
    p.samples_per_pixel = end;
    const Film film = render(scene, p).film;
    std::vector<float> rgb(3 * film.pixel_count());
    for (std::size_t i = 0; i < film.pixel_count(); ++i) {
      const Vec3d m = to_output * film.mean(i);
      for (int c = 0; c < 3; ++c) rgb[3 * i + static_cast<std::size_t>(c)] = static_cast<float>(m[c]);
    }
    return PartialRender{"part", ImageRgbF{24, 20, rgb}, begin, end, "same", film_aov_images(film, to_output)};
  };
  const PartialRender whole = part(0, 10);
  const MergedRender merged = merge_partial_renders({part(0, 3), part(3, 10)});
  ASSERT_EQ(merged.aovs.variance.rgb.size(), whole.aovs.variance.rgb.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < whole.aovs.variance.rgb.size(); ++i) {
    const double w = whole.aovs.variance.rgb[i], m = merged.aovs.variance.rgb[i];
    EXPECT_NEAR(m, w, 1e-4 * w + 1e-12) << "value " << i;
    largest = std::max(largest, w);
  }
  EXPECT_GT(largest, 0.0);
}

}  // namespace
}  // namespace prism
