// Adaptive sampling (render/adaptive_sampling.h): the rule on hand-made films, and renders
// that must (a) converge to the image of uniform sampling (Z scores against an independent
// uniform render, as tests/render/reference_path_tracer_test.cpp), (b) be bitwise the same
// for any thread count and pass grouping, (c) resume from a checkpoint to the uninterrupted
// image, (d) stop flat pixels at the minimum and take noisy ones to the cap, and (e) leave
// uniform renders (threshold 0, or a mask that keeps every pixel) exactly as they were.
#include "prism/render/adaptive_sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "prism/core/error.h"
#include "prism/render/aov_images.h"
#include "prism/render/checkpoint.h"
#include "prism/render/color_context.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using test::films_identical;

RenderSettings adaptive_test_settings(int size, int spp, double threshold, int min_samples) {
  RenderSettings s;
  s.width = size;
  s.height = size;
  s.samples_per_pixel = spp;
  s.seed = 5;
  // Independent samples: a pixel's sample variance / n is then its mean's variance, which
  // both the rule and the Z scores rely on.
  s.path.sampler = SamplerKind::independent;
  s.adaptive.noise_threshold = threshold;
  s.adaptive.min_samples = min_samples;
  return s;
}

std::uint32_t adaptive_min_count(const Film& f) { return *std::min_element(f.counts().begin(), f.counts().end()); }
std::uint32_t adaptive_max_count(const Film& f) { return *std::max_element(f.counts().begin(), f.counts().end()); }

TEST(AdaptiveSampling, BoundariesAreMultiplesOfTheMinimumBelowTheCap) {
  AdaptiveSamplingSettings a;
  EXPECT_EQ(next_adaptive_boundary(a, 3, 100), 100);  // off: one segment
  a.noise_threshold = 0.01;
  a.min_samples = 16;
  EXPECT_EQ(next_adaptive_boundary(a, 0, 100), 16);
  EXPECT_EQ(next_adaptive_boundary(a, 15, 100), 16);
  EXPECT_EQ(next_adaptive_boundary(a, 16, 100), 32);
  EXPECT_EQ(next_adaptive_boundary(a, 90, 100), 96);
  EXPECT_EQ(next_adaptive_boundary(a, 96, 100), 100);
}

TEST(AdaptiveSampling, BadSettingsAreUsageErrors) {
  EXPECT_THROW(validate_adaptive_sampling({-0.1, 16}), UsageError);
  EXPECT_THROW(validate_adaptive_sampling({std::nan(""), 16}), UsageError);
  EXPECT_THROW(validate_adaptive_sampling({0.01, 1}), UsageError);
  EXPECT_NO_THROW(validate_adaptive_sampling({0.0, 0}));  // off: the minimum is not used
  RenderSettings s = adaptive_test_settings(8, 16, 0.01, 4);
  s.first_sample = 4;  // --sample-range: refused (docs/farm-rendering.md)
  EXPECT_THROW(validate_render_settings(s), UsageError);
}

// The rule on films of known samples: relative error sqrt(s²/n) / max(|Ȳ|, floor).
TEST(AdaptiveSampling, ErrorIsTheRelativeStandardErrorOfMeanLuminance) {
  Film film(2, 1, AovSet{false, false, false, true});
  // Pixel 0: Y samples 1, 3 (grey, so Y is each channel): mean 2, s² 2, Var[Ȳ] = 1.
  film.add_sample(0, Vec3d(1.0));
  film.add_sample(0, Vec3d(3.0));
  // Pixel 1: dark, Y samples 0, 0.02: mean 0.01, s² 2e-4, Var[Ȳ] = 1e-4.
  film.add_sample(1, Vec3d(0.0));
  film.add_sample(1, Vec3d(0.02));
  const Vec3d row(0.2126, 0.7152, 0.0722);  // sRGB's Y row: sums to 1, so grey Y = value
  EXPECT_NEAR(relative_luminance_error(film, 0, row, 0.0), 1.0 / 2.0, 1e-12);
  EXPECT_NEAR(relative_luminance_error(film, 1, row, 0.0), 0.01 / 0.01, 1e-9);
  // The floor: a tenth of the image mean (2 + 0.01) / 2.
  const double mean = mean_image_luminance(film, row);
  EXPECT_NEAR(mean, 1.005, 1e-12);
  EXPECT_NEAR(relative_luminance_error(film, 1, row, kDarkFloorFraction * mean), 0.01 / 0.1005, 1e-9);
}

// Var[Ȳ] takes the channels' covariance: samples whose channels move against each other
// at constant luminance have no luminance error at all.
TEST(AdaptiveSampling, LuminanceVarianceUsesTheChannelCovariance) {
  Film film(1, 1, AovSet{false, false, false, true});
  const Vec3d row(0.25, 0.5, 0.25);
  film.add_sample(0, Vec3d(2.0, 1.0, 2.0));  // Y = 1.5
  film.add_sample(0, Vec3d(0.0, 2.0, 2.0));  // Y = 1.5
  film.add_sample(0, Vec3d(4.0, 0.0, 2.0));  // Y = 1.5
  EXPECT_LT(relative_luminance_error(film, 0, row, 0.0), 1e-9);
  // The per-channel variances alone would have called it noisy.
  EXPECT_GT(film.variance_of_mean(0).x, 1.0);
}

// The mask: every pixel before the minimum; at a boundary the pixels that took every
// sample and are noisy or next to a noisy one (the one-pixel dilation); between boundaries
// those that took every sample.
TEST(AdaptiveSampling, MaskIsEveryPixelThenTheNoisyDilatedThenTheUnstopped) {
  AdaptiveSamplingSettings a{0.05, 4};
  Film film(5, 1, AovSet{false, false, false, true});
  const color::ColorSpace space = film_color_space(TransportSettings{});  // XYZ: Y is channel 1
  EXPECT_FALSE(adaptive_active_pixels(film, space, a, 0));
  EXPECT_FALSE(adaptive_active_pixels(film, space, a, 3));
  for (int i = 0; i < 4; ++i) {
    for (std::size_t p : {0u, 1u, 2u}) film.add_sample(p, Vec3d(1.0));  // flat
    film.add_sample(3, Vec3d(i % 2 ? 2.0 : 0.1));                        // noisy
    if (i < 3) film.add_sample(4, Vec3d(i % 2 ? 2.0 : 0.1));             // a sample short
  }
  const auto at4 = adaptive_active_pixels(film, space, a, 4);
  ASSERT_TRUE(at4);
  EXPECT_EQ(*at4, (std::vector<std::uint8_t>{0, 0, 1, 1, 0}));  // 2: next to 3
  film.add_sample(2, Vec3d(1.0));
  film.add_sample(3, Vec3d(1.0));
  const auto at5 = adaptive_active_pixels(film, space, a, 5);  // no decision: who took every sample
  ASSERT_TRUE(at5);
  EXPECT_EQ(*at5, (std::vector<std::uint8_t>{0, 0, 1, 1, 0}));
  a.dilate = false;  // then only the noisy pixel itself
  Film undilated(5, 1, AovSet{false, false, false, true});
  for (int i = 0; i < 4; ++i)
    for (std::size_t p = 0; p < 5; ++p) undilated.add_sample(p, p == 3 ? Vec3d(i % 2 ? 2.0 : 0.1) : Vec3d(1.0));
  EXPECT_EQ(*adaptive_active_pixels(undilated, space, a, 4), (std::vector<std::uint8_t>{0, 0, 0, 1, 0}));
}

// Z scores of an adaptive render against an independent uniform one (the reference path
// tracer test's statistics): per 8×8 block Σ(a − u) / sqrt(Σ var), the whole image the same,
// and the fraction of pixel channels past |Z| 4. The adaptive pixel's variance is NOT its own
// estimate, which is biased low exactly where the rule stopped (it stopped because the
// estimate looked small): it is s²/n_a with s² the uniform render's sample variance of the
// pixel, independent of the adaptive samples.
struct AdaptiveAgreement {
  double image_z = 0.0, worst_block_z = 0.0, outlier_fraction = 0.0;
};

AdaptiveAgreement compare_with_uniform(const Film& adaptive, const Film& uniform) {
  AdaptiveAgreement r;
  constexpr int kBlock = 8;
  Vec3d image_d, image_v;
  std::size_t outliers = 0, tested = 0;
  const auto variance = [&](std::size_t p) {
    const double nu = uniform.sample_count(p), na = adaptive.sample_count(p);
    return uniform.variance_of_mean(p) * (nu / na + 1.0);  // s²/n_a + s²/n_u
  };
  for (int by = 0; by < adaptive.height(); by += kBlock)
    for (int bx = 0; bx < adaptive.width(); bx += kBlock) {
      Vec3d block_d, block_v;
      for (int y = by; y < std::min(by + kBlock, adaptive.height()); ++y)
        for (int x = bx; x < std::min(bx + kBlock, adaptive.width()); ++x) {
          const std::size_t p = static_cast<std::size_t>(y) * adaptive.width() + x;
          const Vec3d d = adaptive.mean(p) - uniform.mean(p), v = variance(p);
          block_d += d;
          block_v += v;
          for (int c = 0; c < 3; ++c)
            if (v[c] > 0.0) {
              ++tested;
              outliers += std::abs(d[c]) / std::sqrt(v[c]) > 4.0;
            }
        }
      image_d += block_d;
      image_v += block_v;
      for (int c = 0; c < 3; ++c)
        if (block_v[c] > 0.0) r.worst_block_z = std::max(r.worst_block_z, std::abs(block_d[c]) / std::sqrt(block_v[c]));
    }
  for (int c = 0; c < 3; ++c)
    if (image_v[c] > 0.0) r.image_z = std::max(r.image_z, std::abs(image_d[c]) / std::sqrt(image_v[c]));
  r.outlier_fraction = tested > 0 ? static_cast<double>(outliers) / static_cast<double>(tested) : 0.0;
  return r;
}

// (a) An adaptive render and an independent uniform one (another seed) estimate the same
// image. Bounds as the reference path tracer test's, for the same reasons: |Z| < 4.5 for
// the image, < 5 for every block (≤ 3 × 16 channel-blocks: a normal variate passes 5 with
// probability < 3e-5 for the whole test), pixels past |Z| 4 under 2 %. Stopping a pixel when
// its estimated error is small is known to bias its mean (the estimate correlates with the
// samples); this holds that bias below the noise at the default minimum of 16 samples and
// a threshold that stops most pixels early.
TEST(AdaptiveSampling, ConvergesToTheImageOfUniformSampling) {
  const Scene scene = make_cornell_box();
  for (const TransportKind kind : {TransportKind::spectral, TransportKind::rgb}) {
    RenderSettings s = adaptive_test_settings(32, 256, 0.1, 16);
    s.transport.kind = kind;
    s.seed = 1;
    const RenderResult adaptive = render(scene, s);
    s.adaptive = {};
    s.seed = 2;
    const RenderResult uniform = render(scene, s);
    // The test means something only if the rule stopped pixels at different counts.
    ASSERT_EQ(adaptive_min_count(adaptive.film), 16u);
    ASSERT_EQ(adaptive_max_count(adaptive.film), 256u);
    double total = 0.0;
    for (const std::uint32_t n : adaptive.film.counts()) total += n;
    const AdaptiveAgreement z = compare_with_uniform(adaptive.film, uniform.film);
    std::printf("adaptive vs uniform (%s): mean %.1f spp, image |Z| %.2f, worst block |Z| %.2f, past |Z| 4: %.2f %%\n",
                kind == TransportKind::rgb ? "rgb" : "spectral", total / adaptive.film.pixel_count(), z.image_z,
                z.worst_block_z, 100.0 * z.outlier_fraction);
    EXPECT_LT(z.image_z, 4.5);
    EXPECT_LT(z.worst_block_z, 5.0);
    EXPECT_LT(z.outlier_fraction, 0.02);
  }
}

// Every pixel's samples are those of a uniform render with as many samples: skipping
// stopped pixels (and their camera packets' lanes) changes nothing for the others.
TEST(AdaptiveSampling, EachPixelHoldsTheUniformRendersFirstSamples) {
  const Scene scene = make_cornell_box();
  const RenderSettings s = adaptive_test_settings(24, 48, 0.15, 8);
  const RenderResult adaptive = render(scene, s);
  ASSERT_LT(adaptive_min_count(adaptive.film), adaptive_max_count(adaptive.film));
  for (int n = 8; n <= 48; n += 8) {
    RenderSettings u = s;
    u.adaptive = {};
    u.samples_per_pixel = n;
    u.aovs.variance = true;
    const RenderResult uniform = render(scene, u);
    for (std::size_t p = 0; p < adaptive.film.pixel_count(); ++p)
      if (adaptive.film.sample_count(p) == static_cast<std::uint32_t>(n)) {
        ASSERT_EQ(adaptive.film.sums()[p], uniform.film.sums()[p]) << "pixel " << p << " at " << n;
        ASSERT_EQ(adaptive.film.sum_squares()[p], uniform.film.sum_squares()[p]) << "pixel " << p;
      }
  }
}

// (b) Bitwise the same for 1 and 2 threads, for passes of 1, 3 and 64 samples and passes
// sized by the measured speed, and for both integrators' pixel enumeration.
TEST(AdaptiveSampling, ImageIsIndependentOfThreadsAndPassGrouping) {
  const Scene scene = make_cornell_box();
  for (const IntegratorKind integrator : {IntegratorKind::wavefront, IntegratorKind::reference}) {
    RenderSettings s = adaptive_test_settings(24, 40, 0.15, 8);
    s.integrator = integrator;
    s.threads = 1;
    s.samples_per_pass = 1;
    const RenderResult first = render(scene, s);
    ASSERT_LT(adaptive_min_count(first.film), adaptive_max_count(first.film));
    for (const int threads : {1, 2})
      for (const int pass : {3, 64, 0}) {
        s.threads = threads;
        s.samples_per_pass = pass;
        const RenderResult other = render(scene, s);
        EXPECT_TRUE(films_identical(first.film, other.film)) << threads << " threads, passes of " << pass;
      }
  }
}

// (c) Interrupted (between boundaries and at one) and resumed through a checkpoint file:
// bitwise the uninterrupted image.
TEST(AdaptiveSampling, ResumedRenderIsBitwiseIdenticalToUninterrupted) {
  const Scene scene = make_cornell_box();
  RenderSettings s = adaptive_test_settings(24, 40, 0.15, 8);
  s.samples_per_pass = 1;
  const RenderResult reference = render(scene, s);
  for (const int stop_after : {13, 16}) {
    std::atomic<bool> cancel{false};
    std::optional<Checkpoint> saved;
    RenderHooks hooks;
    hooks.cancel = &cancel;
    hooks.on_pass = [&](const RenderProgress& p) { cancel = p.passes_done == stop_after; };
    hooks.on_checkpoint = [&](const Film& film, int next) { saved = Checkpoint{image_fingerprint(scene, s), 0, next, film}; };
    const RenderResult interrupted = render(scene, s, hooks);
    ASSERT_EQ(interrupted.stop_reason, StopReason::cancelled);
    ASSERT_TRUE(saved);
    ASSERT_EQ(saved->next_sample, stop_after);
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("prism-adaptive-resume-" + std::to_string(::getpid()) + ".ckp");
    write_checkpoint(path, *saved);
    const Checkpoint loaded = read_checkpoint(path);
    std::filesystem::remove(path);
    RenderSettings resumed_settings = s;
    resumed_settings.threads = 2;
    resumed_settings.samples_per_pass = 0;
    const ResumeState resume{loaded.film, loaded.next_sample};
    const RenderResult resumed = render(scene, resumed_settings, RenderHooks{}, &resume);
    EXPECT_TRUE(films_identical(resumed.film, reference.film)) << "stopped after " << stop_after;
  }
}

// (d) Pixels whose luminance does not vary from sample to sample (the light seen directly:
// its spectrum's luminance is the same at every wavelength sample), nor their neighbours',
// stop at the minimum;
// pixels whose relative error at the cap is still over twice the threshold (an
// independent uniform render says) must have sampled to the cap. The sample-count AOV
// shows the film's counts.
TEST(AdaptiveSampling, FlatPixelsStopAtTheMinimumNoisyOnesGoToTheCap) {
  const Scene scene = make_cornell_box();
  constexpr int kSize = 96;  // the light then covers pixels whose neighbours are all on it
  RenderSettings s = adaptive_test_settings(kSize, 64, 0.02, 8);
  s.aovs.sample_count = true;
  const RenderResult adaptive = render(scene, s);
  const AovImages counts = film_aov_images(adaptive.film, Mat3::identity());
  ASSERT_EQ(counts.sample_count.size(), adaptive.film.pixel_count());
  RenderSettings u = s;
  u.adaptive = {};
  u.aovs.variance = true;
  u.seed = 6;
  const RenderResult uniform = render(scene, u);
  const Vec3d row = adaptive.film_space.rgb_to_xyz.row(1);
  const double floor = kDarkFloorFraction * mean_image_luminance(uniform.film, row);
  int flat = 0, noisy = 0, noisy_at_cap = 0;
  for (std::size_t p = 0; p < adaptive.film.pixel_count(); ++p) {
    EXPECT_EQ(counts.sample_count[p], static_cast<float>(adaptive.film.sample_count(p)));
    const double error = relative_luminance_error(uniform.film, p, row, floor);
    // Flat with all its neighbours (the mask is dilated by one pixel).
    const int x = static_cast<int>(p % kSize), y = static_cast<int>(p / kSize);
    bool flat_around = true;
    for (int dy = std::max(0, y - 1); dy <= std::min(kSize - 1, y + 1); ++dy)
      for (int dx = std::max(0, x - 1); dx <= std::min(kSize - 1, x + 1); ++dx)
        flat_around &= relative_luminance_error(uniform.film, static_cast<std::size_t>(dy) * kSize + dx, row, floor) == 0.0;
    if (flat_around) {
      ++flat;
      EXPECT_EQ(adaptive.film.sample_count(p), 8u) << "flat pixel " << p;
    } else if (error > 2.0 * s.adaptive.noise_threshold) {
      ++noisy;
      noisy_at_cap += adaptive.film.sample_count(p) == 64u;
    }
  }
  std::printf("flat pixels %d, noisy %d, of them at the cap %d\n", flat, noisy, noisy_at_cap);
  ASSERT_GT(flat, 0);
  ASSERT_GT(noisy, 100);
  // A pixel whose error at 64 samples is over 2T has an error over 2.1T at 56, and stops
  // there only if its sample variance is under a quarter of the true one; with 56 samples
  // that is rare, though not for the heavy-tailed pixels of caustic paths: 95 %.
  EXPECT_GE(noisy_at_cap, noisy * 95 / 100);
}

// (e) Threshold 0 is uniform sampling: no variance AOV added, the same fingerprint, and
// the image of a render that never heard of adaptive sampling. And a mask that keeps every
// pixel (a threshold no pixel meets) gives the uniform image bit for bit, in both
// integrators: the masked paths enumerate the same samples in the same order.
TEST(AdaptiveSampling, ThresholdZeroAndAnAllActiveMaskAreUniformSampling) {
  const Scene scene = make_cornell_box();
  RenderSettings uniform = adaptive_test_settings(24, 24, 0.0, 4);
  EXPECT_EQ(adaptive_film_aovs(uniform.aovs, uniform.adaptive), AovSet{});
  RenderSettings plain;
  plain.width = plain.height = 24;
  plain.samples_per_pixel = 24;
  plain.seed = 5;
  plain.path.sampler = SamplerKind::independent;
  EXPECT_EQ(image_fingerprint(scene, uniform), image_fingerprint(scene, plain));
  EXPECT_TRUE(films_identical(render(scene, uniform).film, render(scene, plain).film));
  // Without the light in view (its pixels' luminance is exact) nor the void around the box
  // (black, exactly): a 20° view of the back wall and the blocks, every pixel noisy.
  Scene no_light = scene;
  no_light.camera.fov_degrees = 20.0f;
  for (const IntegratorKind integrator : {IntegratorKind::wavefront, IntegratorKind::reference}) {
    RenderSettings all_active = adaptive_test_settings(24, 24, 1e-12, 8);
    all_active.integrator = integrator;
    plain.integrator = integrator;
    const RenderResult a = render(no_light, all_active);
    ASSERT_EQ(adaptive_min_count(a.film), 24u);  // no pixel meets 1e-12
    EXPECT_TRUE(films_identical(a.film, render(no_light, plain).film));
  }
  EXPECT_NE(image_fingerprint(scene, adaptive_test_settings(24, 24, 0.01, 16)), image_fingerprint(scene, plain));
  EXPECT_NE(image_fingerprint(scene, adaptive_test_settings(24, 24, 0.01, 16)),
            image_fingerprint(scene, adaptive_test_settings(24, 24, 0.02, 16)));
  RenderSettings undilated = adaptive_test_settings(24, 24, 0.01, 16);
  undilated.adaptive.dilate = false;
  EXPECT_NE(image_fingerprint(scene, undilated), image_fingerprint(scene, adaptive_test_settings(24, 24, 0.01, 16)));
}

}  // namespace
}  // namespace prism
