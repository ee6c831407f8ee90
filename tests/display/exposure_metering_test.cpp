// Exposure metering (display/exposure_metering.h) on synthetic films whose right answer is
// known in closed form, and against a brute-force oracle (every zone sorted by luminance,
// the weighted quantiles found by walking the sorted list) on random films.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "prism/core/error.h"
#include "prism/color/color_space.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/exposure.h"
#include "prism/display/exposure_metering.h"

namespace prism::display {
namespace {

const Vec3d kRec709Y{0.2126, 0.7152, 0.0722};

// Tolerance of a metered EV: the histogram's bins are 1/64 EV wide and the mean of a bin
// is taken at its centre (≤ 1/128 EV), and the result is rounded to 1/100 EV (≤ 0.005).
constexpr double kEvTolerance = 1.0 / 128.0 + 0.005;

double ev_for(double luminance) { return std::log2(luminance / (1.2 * 0.18)); }

ImageRgbF grey_film(int w, int h, float y) { return {w, h, std::vector<float>(3 * std::size_t(w) * h, y)}; }

void set_pixel(ImageRgbF& f, int x, int y, float v) {
  for (int c = 0; c < 3; ++c) f.rgb[3 * (std::size_t(y) * f.width + x) + c] = v;
}

// Left half: the void (black, coverage 0: no camera ray hits); right half: grey content of
// `content_nits` (coverage 1).
struct HalfVoidFilm {
  ImageRgbF film;
  std::vector<float> coverage;
};
HalfVoidFilm half_void_film(int w, int h, float content_nits) {
  HalfVoidFilm f{grey_film(w, h, content_nits), std::vector<float>(std::size_t(w) * h, 1.0f)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w / 2; ++x) {
      set_pixel(f.film, x, y, 0.0f);
      f.coverage[std::size_t(y) * w + x] = 0.0f;
    }
  return f;
}

TEST(ExposureMetering, VoidIsNotMeteredContentGoesToTheKey) {
  const auto [film, coverage] = half_void_film(128, 64, 0.5f);
  const MeteredExposure m = meter_exposure(film, kRec709Y, coverage, {});
  EXPECT_NEAR(m.ev100, ev_for(0.5), kEvTolerance);
  EXPECT_NEAR(m.covered_fraction, 0.5, 1e-12);
  EXPECT_FALSE(m.clamped);
  // The content exposes to the key (0.18) within the EV tolerance.
  EXPECT_NEAR(0.5 / (1.2 * std::exp2(m.ev100)), 0.18, 0.18 * (std::exp2(kEvTolerance) - 1.0));
  // Without coverage the black half drags the meter far down (over-exposing the content).
  const MeteredExposure blind = meter_exposure(film, kRec709Y, {}, {});
  EXPECT_LT(blind.ev100, m.ev100 - 3.0);
}

// The display pipeline's --auto-exposure (what `prism tonemap` runs) meters with the
// coverage it is given, and refuses one of the wrong size.
TEST(ExposureMetering, DisplaySettingsCarryTheCoverage) {
  const auto [film, coverage] = half_void_film(64, 32, 0.5f);
  const color::ColorSpace& srgb = color::color_space("srgb");
  DisplaySettings s;
  s.auto_exposure = true;
  const double blind_scale = exposure_scale(s, film, srgb);
  s.metering_coverage = coverage;
  const double scale = exposure_scale(s, film, srgb);
  const MeteredExposure m = meter_exposure(film, srgb.rgb_to_xyz.row(1), coverage, {});
  EXPECT_DOUBLE_EQ(scale, exposure_scale_from_ev100(m.ev100));
  EXPECT_LT(scale, blind_scale / 8.0);  // the void no longer pulls the meter ≥ 3 EV down
  s.metering_coverage.pop_back();
  EXPECT_THROW(exposure_scale(s, film, srgb), UsageError);
}

TEST(ExposureMetering, DarkestAndBrightestTailsAreIgnored) {
  // 32 rows of zones (side 4): 2 rows of light sources (1e3 nit), 2 of deep shadow
  // (1e-3 nit), the rest 2 nit. Each tail (6.25 %) lies inside the discarded 10 %.
  const int w = 128, h = 128;
  ImageRgbF film = grey_film(w, h, 2.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < w; ++x) set_pixel(film, x, y, 1e3f);
  for (int y = h - 8; y < h; ++y)
    for (int x = 0; x < w; ++x) set_pixel(film, x, y, 1e-3f);
  const MeteredExposure m = meter_exposure(film, kRec709Y, {}, {});
  EXPECT_NEAR(m.ev100, ev_for(2.0), kEvTolerance);
  // Keeping the tails (0–100 %) moves the meter to the log mean of all zones.
  MeteringSettings all;
  all.low_percentile = 0.0;
  all.high_percentile = 1.0;
  const double log2_mean = (2 * std::log2(1e3) + 2 * std::log2(1e-3) + 28 * 1.0) / 32.0;
  EXPECT_NEAR(meter_exposure(film, kRec709Y, {}, all).ev100, log2_mean - std::log2(1.2 * 0.18), kEvTolerance);
}

TEST(ExposureMetering, NanPixelsAreNotMetered) {
  ImageRgbF film = grey_film(64, 64, 0.3f);
  for (int x = 0; x < 64; ++x) set_pixel(film, x, 5, std::numeric_limits<float>::quiet_NaN());
  set_pixel(film, 7, 9, std::numeric_limits<float>::infinity());
  EXPECT_NEAR(meter_exposure(film, kRec709Y, {}, {}).ev100, ev_for(0.3), kEvTolerance);
}

TEST(ExposureMetering, ClampedToTheEvRange) {
  MeteringSettings s;
  const MeteredExposure bright = meter_exposure(grey_film(32, 32, 1e12f), kRec709Y, {}, s);
  EXPECT_EQ(bright.ev100, s.ev100_max);
  EXPECT_TRUE(bright.clamped);
  const MeteredExposure dark = meter_exposure(grey_film(32, 32, 1e-12f), kRec709Y, {}, s);
  EXPECT_EQ(dark.ev100, s.ev100_min);
  EXPECT_TRUE(dark.clamped);
  s.ev100_min = 2.0;
  s.ev100_max = 3.0;
  EXPECT_EQ(meter_exposure(grey_film(32, 32, 0.1f), kRec709Y, {}, s).ev100, 2.0);
  // Nothing lit at all: EV100 0, not the clamp's end (no gain of 2^10 on black).
  EXPECT_EQ(meter_exposure(grey_film(32, 32, 0.0f), kRec709Y, {}, {}).ev100, 0.0);
}

TEST(ExposureMetering, CentreWeightingFavoursTheCentre) {
  // A bright centre square (a quarter of the pixels, 4 nit) in a dim surround (0.25 nit).
  const int n = 128;
  ImageRgbF film = grey_film(n, n, 0.25f);
  for (int y = n / 4; y < 3 * n / 4; ++y)
    for (int x = n / 4; x < 3 * n / 4; ++x) set_pixel(film, x, y, 4.0f);
  MeteringSettings uniform, centre;
  centre.centre_weight = 1.0;
  const double ev_uniform = meter_exposure(film, kRec709Y, {}, uniform).ev100;
  const double ev_centre = meter_exposure(film, kRec709Y, {}, centre).ev100;
  // Uniform: 75 % of the weight dim, 25 % bright; the window [lo, hi] keeps the dim zones
  // from lo to 0.75 and the bright ones from 0.75 to hi (10–90 %: 65 % dim, 15 % bright).
  const auto trimmed_ev = [](double lo, double hi, double dim_share) {
    const double dim = std::max(0.0, std::min(dim_share, hi) - lo);
    const double bright = std::max(0.0, hi - std::max(dim_share, lo));
    return (dim * std::log2(0.25) + bright * std::log2(4.0)) / (hi - lo) - std::log2(0.216);
  };
  EXPECT_NEAR(ev_uniform, trimmed_ev(uniform.low_percentile, uniform.high_percentile, 0.75), kEvTolerance);
  // Centre-weighted: each zone (4² pixels) weighs exp(−r²/(2·0.4²)), r its centre's
  // distance from the image centre in half-diagonals; the bright square's share b of the
  // weight sets the window: dim from the low quantile to 1 − b, bright from 1 − b to the high.
  double bright = 0, total = 0;
  for (int zy = 0; zy < n / 4; ++zy)
    for (int zx = 0; zx < n / 4; ++zx) {
      const double r = std::hypot(4 * zx + 2 - n / 2.0, 4 * zy + 2 - n / 2.0) / (n * std::sqrt(0.5));
      const double wgt = std::exp(-r * r / (2 * 0.4 * 0.4));
      total += wgt;
      if (zx >= n / 16 && zx < 3 * n / 16 && zy >= n / 16 && zy < 3 * n / 16) bright += wgt;
    }
  const double b = bright / total;
  ASSERT_GT(b, 0.4);  // the square (a quarter of the pixels) carries far more than a quarter
  EXPECT_NEAR(ev_centre, trimmed_ev(centre.low_percentile, centre.high_percentile, 1.0 - b), kEvTolerance);
  EXPECT_GT(ev_centre, ev_uniform + 0.5);
  // Symmetric content: centre weighting changes nothing.
  const ImageRgbF flat = grey_film(n, n, 1.0f);
  EXPECT_EQ(meter_exposure(flat, kRec709Y, {}, centre).ev100, meter_exposure(flat, kRec709Y, {}, uniform).ev100);
}

// Brute force: zones as meter_exposure defines them, sorted, quantiles by walking.
double oracle_ev(const ImageRgbF& f, const std::vector<float>& cov, double lo_q, double hi_q) {
  const int side = std::max(1, std::min(f.width, f.height) / 32);
  std::vector<std::pair<double, double>> zones;  // (log2 Y, weight)
  for (int y0 = 0; y0 < f.height; y0 += side)
    for (int x0 = 0; x0 < f.width; x0 += side) {
      double sc = 0, scy = 0;
      for (int y = y0; y < std::min(f.height, y0 + side); ++y)
        for (int x = x0; x < std::min(f.width, x0 + side); ++x) {
          const std::size_t i = std::size_t(y) * f.width + x;
          const double lum = kRec709Y.x * f.rgb[3 * i] + kRec709Y.y * f.rgb[3 * i + 1] + kRec709Y.z * f.rgb[3 * i + 2];
          sc += cov[i];
          scy += cov[i] * lum;
        }
      if (sc > 0) zones.emplace_back(std::log2(scy / sc), sc);
    }
  std::sort(zones.begin(), zones.end());
  double total = 0;
  for (const auto& z : zones) total += z.second;
  double below = 0, sum = 0, kept = 0;
  for (const auto& [v, wgt] : zones) {
    const double overlap = std::max(0.0, std::min(below + wgt, hi_q * total) - std::max(below, lo_q * total));
    sum += overlap * v;
    kept += overlap;
    below += wgt;
  }
  return sum / kept - std::log2(1.2 * 0.18);
}

TEST(ExposureMetering, MatchesBruteForceQuantilesOnRandomFilms) {
  std::mt19937 rng(7);
  std::lognormal_distribution<float> lum(0.0f, 2.0f);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int trial = 0; trial < 5; ++trial) {
    const int w = 96 + 17 * trial, h = 64 + 9 * trial;  // partial zones at the edges
    ImageRgbF film{w, h, std::vector<float>(3 * std::size_t(w) * h)};
    std::vector<float> cov(std::size_t(w) * h);
    for (std::size_t i = 0; i < cov.size(); ++i) {
      const float y = lum(rng);
      for (int c = 0; c < 3; ++c) film.rgb[3 * i + c] = y * (0.5f + u(rng));
      cov[i] = u(rng) < 0.3f ? 0.0f : u(rng);
    }
    MeteringSettings s;
    s.low_percentile = 0.05 * trial;
    s.high_percentile = 0.7 + 0.05 * trial;
    EXPECT_NEAR(meter_exposure(film, kRec709Y, cov, s).ev100, oracle_ev(film, cov, s.low_percentile, s.high_percentile),
                kEvTolerance)
        << trial;
  }
}

TEST(ExposureMetering, OneSampleNoiseDoesNotBiasTheMeter) {
  // A 1-spp film: each pixel is 4·Y with probability 1/4, else 0 (mean Y = 1 nit). Zones
  // of 16² pixels average 256 such samples: relative std √(3/256) ≈ 0.108, so the log
  // mean's Jensen bias is ≈ σ²/(2 ln 2) ≈ 0.009 EV; 0.05 EV bounds it with margin.
  const int n = 512;
  ImageRgbF film = grey_film(n, n, 0.0f);
  std::mt19937 rng(3);
  std::bernoulli_distribution hit(0.25);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (hit(rng)) set_pixel(film, x, y, 4.0f);
  EXPECT_NEAR(meter_exposure(film, kRec709Y, {}, {}).ev100, ev_for(1.0), 0.05);
}

TEST(ExposureMetering, RejectsBadSettingsAndSizes) {
  MeteringSettings s;
  s.low_percentile = 0.9;
  s.high_percentile = 0.5;
  EXPECT_THROW(meter_exposure(grey_film(4, 4, 1), kRec709Y, {}, s), UsageError);
  s = {};
  s.centre_weight = 2;
  EXPECT_THROW(validate_metering_settings(s), UsageError);
  EXPECT_THROW(meter_exposure(grey_film(4, 4, 1), kRec709Y, std::vector<float>(3, 1.0f), {}), Error);
}

TEST(ExposureMetering, AdaptationIsExponentialInEv) {
  EXPECT_EQ(adapt_ev100(std::nullopt, 3.0, 0.1, 2.0), 3.0);  // first frame: the metered EV
  // speed ln 2 per second: half the distance in one second, three quarters in two.
  EXPECT_NEAR(adapt_ev100(0.0, 4.0, 1.0, std::log(2.0)), 2.0, 1e-12);
  EXPECT_NEAR(adapt_ev100(0.0, 4.0, 2.0, std::log(2.0)), 3.0, 1e-12);
  EXPECT_EQ(adapt_ev100(1.0, 4.0, 0.0, 5.0), 1.0);
  EXPECT_EQ(adapt_ev100(1.0, 4.0, 0.5, INFINITY), 4.0);
  EXPECT_EQ(adapt_ev100(1.0, 4.0, 0.5, 0.0), 1.0);
}

}  // namespace
}  // namespace prism::display
