#include "prism/denoise/denoiser.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/denoise/demodulation.h"

namespace prism::denoise {
namespace {

// Bounds that keep every term of the colour distance finite (squared differences up to
// 4e30, variance sums up to 2e30), so that no NaN can arise from inf − inf; far beyond any
// radiance a render produces.
constexpr float kMaxMagnitude = 1e15f;
constexpr float kMaxVariance = 1e30f;

std::vector<float> channel(const std::vector<float>& interleaved, int c, int stride) {
  std::vector<float> out(interleaved.size() / stride);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = interleaved[i * stride + c];
  return out;
}

// Depth in units of the image's mean finite depth, so that the feature floor τ means the
// same in millimetre and metre scenes; pixels that saw no surface get 0 (they also differ
// from every surface pixel in albedo and normal, which separates them).
std::vector<float> normalized_depth(const std::vector<float>& depth) {
  double sum = 0.0;
  std::size_t n = 0;
  for (float z : depth)
    if (std::isfinite(z) && z > 0.0f) sum += z, ++n;
  const float scale = n > 0 && sum > 0.0 ? static_cast<float>(static_cast<double>(n) / sum) : 1.0f;
  std::vector<float> out(depth.size());
  for (std::size_t i = 0; i < depth.size(); ++i)
    out[i] = std::isfinite(depth[i]) && depth[i] > 0.0f ? depth[i] * scale : 0.0f;
  return out;
}

NlmFeature rgb_feature(const std::vector<float>& interleaved) {
  NlmFeature f;
  for (int c = 0; c < 3; ++c) f.channels.push_back(channel(interleaved, c, 3));
  for (auto& plane : f.channels)
    for (float& v : plane)
      if (!std::isfinite(v)) v = 0.0f;
  return f;
}

}  // namespace

void check_denoise_settings(const DenoiseSettings& s) {
  const auto radius = [](int r, const char* name) {
    if (r < 0 || r > 32) throw UsageError(fmt::format("denoiser {} {} is outside 0..32", name, r));
  };
  radius(s.nlm.search_radius, "search radius");
  radius(s.nlm.patch_radius, "patch radius");
  if (!(s.nlm.color_sensitivity > 0.0f) || !(s.nlm.feature_sensitivity > 0.0f) || !(s.nlm.feature_floor > 0.0f) ||
      !(s.nlm.variance_cancellation >= 0.0f))
    throw UsageError("denoiser sensitivities must be positive");
}

ImageRgbF denoise_image(const DenoiseBuffers& b, const DenoiseSettings& settings) {
  check_denoise_buffers(b);
  check_denoise_settings(settings);
  const std::size_t n = b.pixel_count();
  const std::vector<float> divisor = demodulation_divisors(b.albedo);
  NlmImage im;
  im.width = b.width;
  im.height = b.height;
  for (int c = 0; c < 3; ++c) {
    im.color[c].resize(n);
    im.variance[c].resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const float u = b.color[3 * i + c], v = b.variance[3 * i + c], d = divisor[3 * i + c];
      const bool ok = std::isfinite(u);
      im.color[c][i] = ok ? std::clamp(u / d, -kMaxMagnitude, kMaxMagnitude) : 0.0f;
      im.variance[c][i] = ok && std::isfinite(v) && v > 0.0f ? std::min(v / (d * d), kMaxVariance) : 0.0f;
    }
  }
  im.features.push_back(rgb_feature(b.normal));
  im.features.push_back(NlmFeature{{normalized_depth(b.depth)}});
  im.features.push_back(rgb_feature(b.albedo));
  const auto filtered = nlm_feature_filter(im, settings.nlm);
  ImageRgbF out{b.width, b.height, std::vector<float>(3 * n)};
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = filtered[c][i] * divisor[3 * i + c];
  return out;
}

}  // namespace prism::denoise
