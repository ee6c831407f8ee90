// The denoiser on a real render: the Cornell box at 16 spp against a 512-spp reference.
#include <gtest/gtest.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/denoise/denoiser.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "support/mean_of.h"

namespace prism::denoise {
namespace {

struct Rendered {
  std::vector<float> rgb;  // working (sRGB-linear) means
  DenoiseBuffers buffers;
};

Rendered render_cornell(int size, int spp, std::uint64_t seed) {
  RenderSettings s;
  s.width = s.height = size;
  s.samples_per_pixel = spp;
  s.seed = seed;
  s.aovs = {true, true, true, true};
  const RenderResult r = render(make_cornell_box(), s);
  const Mat3 to_srgb = color::conversion_matrix(r.film_space, color::color_space("srgb"));
  Rendered out;
  out.buffers = film_denoise_buffers(r.film, to_srgb);
  out.rgb = out.buffers.color;
  return out;
}

// pbrt-v4's relative MSE, (x − r)² / (r² + 0.01), over pixels and channels, leaving out the
// directly visible light (reference luminance above half the maximum) as bench does.
double relative_mse(const std::vector<float>& x, const std::vector<float>& ref) {
  float max_sum = 0.0f;
  for (std::size_t i = 0; i < ref.size(); i += 3) max_sum = std::max(max_sum, ref[i] + ref[i + 1] + ref[i + 2]);
  double s = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < ref.size(); i += 3) {
    if (ref[i] + ref[i + 1] + ref[i + 2] > 0.5f * max_sum) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = x[i + c] - ref[i + c];
      s += d * d / (ref[i + c] * ref[i + c] + 0.01);
      ++n;
    }
  }
  return s / static_cast<double>(n);
}

using test::mean_of;  // support/mean_of.h

TEST(DenoiserCornellBox, LowSppErrorDropsAndTheMeanHolds) {
  const Rendered reference = render_cornell(64, 512, 99);
  const Rendered noisy = render_cornell(64, 16, 1);
  const ImageRgbF denoised = denoise_image(noisy.buffers);
  const double noisy_error = relative_mse(noisy.rgb, reference.rgb);
  const double denoised_error = relative_mse(denoised.rgb, reference.rgb);
  RecordProperty("relMSE_noisy", std::to_string(noisy_error));
  RecordProperty("relMSE_denoised", std::to_string(denoised_error));
  std::printf("relMSE noisy %.5f denoised %.5f, mean ratio %.4f\n", noisy_error, denoised_error,
              mean_of(denoised.rgb) / mean_of(reference.rgb));
  // Measured: 5.3× lower at this small size (9.8× at 128², where the box's flat walls cover
  // more pixels per search window). 4× leaves room for other seeds; no filtering gives 1×,
  // and smearing the box's edges raises the error above the noisy image's.
  EXPECT_LT(denoised_error, noisy_error / 4.0);
  // The bound on the image mean: 1 %.
  EXPECT_NEAR(mean_of(denoised.rgb) / mean_of(reference.rgb), 1.0, 0.01);
}

}  // namespace
}  // namespace prism::denoise
