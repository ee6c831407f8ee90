#include "prism/denoise/denoiser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "support/mean_of.h"

namespace prism::denoise {
namespace {

// A flat, camera-facing wall of uniform albedo at depth 10: features that separate nothing.
DenoiseBuffers flat_wall(int width, int height, float albedo = 0.5f) {
  DenoiseBuffers b;
  b.width = width;
  b.height = height;
  const std::size_t n = b.pixel_count();
  b.color.assign(3 * n, 0.0f);
  b.variance.assign(3 * n, 0.0f);
  b.albedo.assign(3 * n, albedo);
  b.normal.assign(3 * n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) b.normal[3 * i + 2] = 1.0f;
  b.depth.assign(n, 10.0f);
  return b;
}

// Gaussian noise of relative standard deviation `relative_sigma` on every channel, with the
// exact variance of that noise in the variance buffer (as a converged variance AOV would hold).
void add_noise(DenoiseBuffers& b, float relative_sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  for (std::size_t i = 0; i < b.color.size(); ++i) {
    const float sigma = relative_sigma * b.color[i];
    b.color[i] += sigma * gauss(rng);
    b.variance[i] = sigma * sigma;
  }
}

using test::mean_of;  // support/mean_of.h

// Mean over rows of channel 0, per column.
std::vector<double> column_profile(const std::vector<float>& rgb, int width, int height) {
  std::vector<double> p(width, 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) p[x] += rgb[3 * (static_cast<std::size_t>(y) * width + x)] / height;
  return p;
}

// 10–90 % rise width of a monotone step in a profile, in pixels, with linear interpolation
// between columns (an ideal one-pixel step gives 0.8).
double rise_width_10_90(const std::vector<double>& p, double low, double high) {
  const auto crossing = [&](double level) {
    for (std::size_t x = 1; x < p.size(); ++x)
      if ((p[x - 1] - level) * (p[x] - level) <= 0.0 && p[x] != p[x - 1])
        return static_cast<double>(x - 1) + (level - p[x - 1]) / (p[x] - p[x - 1]);
    return -1.0;
  };
  const double a = crossing(low + 0.1 * (high - low)), b = crossing(low + 0.9 * (high - low));
  return a < 0.0 || b < 0.0 ? 1e9 : std::abs(b - a);
}

TEST(Denoiser, ConstantImageUnchanged) {
  DenoiseBuffers b = flat_wall(40, 30);
  for (std::size_t i = 0; i < b.color.size(); ++i) {
    b.color[i] = 0.25f + 0.25f * static_cast<float>(i % 3);
    b.variance[i] = 0.01f;
  }
  const ImageRgbF out = denoise_image(b);
  // Each output is Σ w·c / Σ w over the (2r+1)² equal values of its window: float rounding
  // of that many sums bounds the relative change by (2r+1)² · 2⁻²⁴.
  const int window = 2 * NlmParameters{}.search_radius + 1;
  const float tolerance = static_cast<float>(window * window) * 0x1p-24f;
  for (std::size_t i = 0; i < out.rgb.size(); ++i) EXPECT_NEAR(out.rgb[i], b.color[i], tolerance * b.color[i]) << i;
}

TEST(Denoiser, NoiseFreeSmoothImageUnchanged) {
  // A smooth ramp with zero variance: every difference between pixels is signal, so the
  // colour distance (differences over ε = 1e-10) gives other pixels weights ≤ e⁻³⁰.
  DenoiseBuffers b = flat_wall(40, 30);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x)
      for (int c = 0; c < 3; ++c) b.color[3 * (y * b.width + x) + c] = 0.1f + 0.02f * x + 0.01f * y + 0.1f * c;
  const ImageRgbF out = denoise_image(b);
  // At most 224 neighbours of weight ≤ 9.4e-14 each, colours within a factor 10 of the pixel's.
  for (std::size_t i = 0; i < out.rgb.size(); ++i) EXPECT_NEAR(out.rgb[i], b.color[i], 1e-6f * b.color[i]) << i;
}

TEST(Denoiser, KeepsTheMeanAndRemovesNoise) {
  DenoiseBuffers b = flat_wall(64, 48);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x)
      for (int c = 0; c < 3; ++c) b.color[3 * (y * b.width + x) + c] = 0.6f + 0.4f * std::sin(0.1f * x) * std::cos(0.07f * y);
  const std::vector<float> truth = b.color;
  add_noise(b, 0.3f, 7);
  const ImageRgbF out = denoise_image(b);
  const double true_mean = mean_of(truth);
  // The bound on the image mean: 1 %.
  EXPECT_NEAR(mean_of(out.rgb) / true_mean, 1.0, 0.01);
  double noisy_se = 0.0, out_se = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    noisy_se += (b.color[i] - truth[i]) * (b.color[i] - truth[i]);
    out_se += (out.rgb[i] - truth[i]) * (out.rgb[i] - truth[i]);
  }
  // An 11² window of independent noise could reduce the error up to 121×; 5× is well inside
  // what the filter reaches on this slowly varying signal, and far from 1× (no filtering).
  EXPECT_LT(out_se, noisy_se / 5.0);
}

TEST(Denoiser, EdgeBetweenDifferentlyLitRegionsStaysSharp) {
  // A shadow edge: one wall, one albedo, one normal; the left half lit (1.0), the right half
  // in shadow (0.2). Only the colour distance can tell the halves apart.
  DenoiseBuffers b = flat_wall(48, 48);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x)
      for (int c = 0; c < 3; ++c) b.color[3 * (y * b.width + x) + c] = x < 24 ? 1.0f : 0.2f;
  add_noise(b, 0.1f, 11);
  const ImageRgbF out = denoise_image(b);
  const auto profile = column_profile(out.rgb, b.width, b.height);
  // Ideal step: 0.8 px. A box blur of the search window's width would give about 12 px.
  EXPECT_LE(rise_width_10_90(profile, 0.2, 1.0), 2.0);
}

TEST(Denoiser, GeometricEdgeStaysSharpUnderHeavyNoise) {
  // Two walls meeting at a crease, differently lit, with noise so strong (50 %) that colour
  // alone cannot separate them: the normals must.
  DenoiseBuffers b = flat_wall(48, 48);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * b.width + x;
      for (int c = 0; c < 3; ++c) b.color[3 * i + c] = x < 24 ? 1.0f : 0.4f;
      if (x >= 24) b.normal[3 * i] = 1.0f, b.normal[3 * i + 2] = 0.0f;
    }
  add_noise(b, 0.5f, 13);
  const ImageRgbF out = denoise_image(b);
  EXPECT_LE(rise_width_10_90(column_profile(out.rgb, b.width, b.height), 0.4, 1.0), 2.0);
}

TEST(Denoiser, AlbedoTextureDetailSurvives) {
  // A one-pixel checkerboard texture (albedo 0.2 / 0.8) under uniform light of radiance 1
  // with 30 % noise. After demodulation the filter sees a flat irradiance; remodulating by
  // each pixel's albedo must bring the checker back at full contrast.
  DenoiseBuffers b = flat_wall(48, 48);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * b.width + x;
      const float a = (x + y) % 2 ? 0.8f : 0.2f;
      for (int c = 0; c < 3; ++c) b.albedo[3 * i + c] = a, b.color[3 * i + c] = a;
    }
  const std::vector<float> truth = b.color;
  add_noise(b, 0.3f, 17);
  const ImageRgbF out = denoise_image(b);
  double dark = 0.0, bright = 0.0, noisy_se = 0.0, out_se = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    (truth[i] < 0.5f ? dark : bright) += out.rgb[i] / (truth.size() / 2.0);
    noisy_se += (b.color[i] - truth[i]) * (b.color[i] - truth[i]);
    out_se += (out.rgb[i] - truth[i]) * (out.rgb[i] - truth[i]);
  }
  // Blurring the texture would pull both means towards 0.5; 3 % is about ten standard
  // errors of each mean of the noisy input (0.3·a / √1152).
  EXPECT_NEAR(dark, 0.2, 0.2 * 0.03);
  EXPECT_NEAR(bright, 0.8, 0.8 * 0.03);
  EXPECT_LT(out_se, noisy_se / 5.0);  // and the noise is still removed
}

TEST(Denoiser, SameResultForAnyThreadCount) {
  DenoiseBuffers b = flat_wall(50, 70);  // 70 rows: three bands of rows, the last partial
  for (std::size_t i = 0; i < b.color.size(); ++i) b.color[i] = 0.3f + 0.001f * static_cast<float>(i % 97);
  add_noise(b, 0.2f, 19);
  ImageRgbF one, two, three;
  {
    const ThreadLimit limit(1);
    one = denoise_image(b);
  }
  {
    const ThreadLimit limit(2);
    two = denoise_image(b);
  }
  {
    const ThreadLimit limit(3);
    three = denoise_image(b);
  }
  ASSERT_EQ(one.rgb.size(), two.rgb.size());
  EXPECT_EQ(std::memcmp(one.rgb.data(), two.rgb.data(), one.rgb.size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(one.rgb.data(), three.rgb.data(), one.rgb.size() * sizeof(float)), 0);
}

TEST(Denoiser, NonFiniteAndHugeInputsGiveFiniteOutput) {
  DenoiseBuffers b = flat_wall(20, 20);
  for (std::size_t i = 0; i < b.color.size(); ++i) b.color[i] = 0.5f, b.variance[i] = 0.01f;
  b.color[30] = std::numeric_limits<float>::infinity();
  b.color[31] = std::numeric_limits<float>::quiet_NaN();
  b.color[90] = b.color[93] = 3e38f;  // neighbours: their difference would overflow
  b.variance[90] = b.variance[93] = 3e38f;
  b.depth[50] = std::numeric_limits<float>::infinity();  // a miss
  const ImageRgbF out = denoise_image(b);
  for (float v : out.rgb) EXPECT_TRUE(std::isfinite(v));
}

TEST(Denoiser, RefusesInconsistentBuffers) {
  DenoiseBuffers b = flat_wall(8, 8);
  b.depth.pop_back();
  EXPECT_THROW(denoise_image(b), Error);
  AovImages aovs;
  aovs.set = {true, true, false, false};
  EXPECT_THROW(denoise_buffers(ImageRgbF{8, 8, std::vector<float>(192)}, aovs), Error);
  EXPECT_EQ(missing_denoise_aovs(aovs.set), (std::vector<std::string>{"depth", "variance"}));
}

}  // namespace
}  // namespace prism::denoise
