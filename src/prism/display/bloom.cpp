#include "prism/display/bloom.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "prism/core/error.h"
#include "prism/display/resampling.h"

namespace prism::display {
namespace {

constexpr double kSigmaPx = 1.5;  // per level; the chain doubles it each level

std::vector<double> gaussian_kernel(double sigma) {
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> k(2 * radius + 1);
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) sum += k[i + radius] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& v : k) v /= sum;  // normalised: the blur keeps the interior's energy
  return k;
}

// One separable pass along x (horizontal) or y, clamped to the edge.
ImageRgbF blur_pass(const ImageRgbF& in, const std::vector<double>& k, bool horizontal) {
  ImageRgbF out{in.width, in.height, std::vector<float>(in.rgb.size())};
  const int radius = static_cast<int>(k.size() / 2);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x)
      for (int c = 0; c < 3; ++c) {
        double acc = 0.0;
        for (int i = -radius; i <= radius; ++i) {
          const int sx = horizontal ? std::clamp(x + i, 0, in.width - 1) : x;
          const int sy = horizontal ? y : std::clamp(y + i, 0, in.height - 1);
          acc += k[i + radius] * in.rgb[3 * (std::size_t(sy) * in.width + sx) + c];
        }
        out.rgb[3 * (std::size_t(y) * in.width + x) + c] = static_cast<float>(acc);
      }
  return out;
}

}  // namespace

BloomThresholdSpace parse_bloom_threshold_space(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n == "hsv") return BloomThresholdSpace::hsv;
  if (n == "rgb") return BloomThresholdSpace::rgb;
  throw UsageError("unknown bloom threshold space '" + std::string(name) + "' (valid: hsv, rgb)");
}

ImageRgbF bloom_bright_pass(const ImageRgbF& image, double t, BloomThresholdSpace space) {
  ImageRgbF out{image.width, image.height, std::vector<float>(image.rgb.size(), 0.0f)};
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    const double r = image.rgb[i], g = image.rgb[i + 1], b = image.rgb[i + 2];
    if (space == BloomThresholdSpace::hsv) {
      const double v = std::max({r, g, b});
      if (!(v > t) || !std::isfinite(v)) continue;
      const double scale = (v - t) / v;  // shrinks V by t, keeping H and S
      out.rgb[i] = static_cast<float>(std::max(r, 0.0) * scale);
      out.rgb[i + 1] = static_cast<float>(std::max(g, 0.0) * scale);
      out.rgb[i + 2] = static_cast<float>(std::max(b, 0.0) * scale);
    } else {
      for (int c = 0; c < 3; ++c) {
        const double v = image.rgb[i + c];
        out.rgb[i + c] = std::isfinite(v) ? static_cast<float>(std::max(v - t, 0.0)) : 0.0f;
      }
    }
  }
  return out;
}

ImageRgbF bloom_halo(const ImageRgbF& bright, int levels) {
  if (levels < 1 || levels > 16) throw UsageError("bloom levels must be in [1, 16]");
  const std::vector<double> kernel = gaussian_kernel(kSigmaPx);
  ImageRgbF halo{bright.width, bright.height, std::vector<float>(bright.rgb.size(), 0.0f)};
  ImageRgbF level = bright;
  // Equal weights: each octave of radius gets the same share of the scattered light.
  const double weight = 1.0 / levels;
  for (int k = 0; k < levels; ++k) {
    if (k > 0) {
      if (level.width == 1 && level.height == 1) break;
      level = downsample_box2(level);  // block means: energy per area is kept
    }
    const ImageRgbF blurred = blur_pass(blur_pass(level, kernel, true), kernel, false);
    const ImageRgbF up = k == 0 ? blurred : upscale_bilinear(blurred, bright.width, bright.height);
    for (std::size_t i = 0; i < halo.rgb.size(); ++i) halo.rgb[i] += static_cast<float>(weight * up.rgb[i]);
  }
  return halo;
}

ImageRgbF bloom_component(const ImageRgbF& image, const BloomSettings& s) {
  if (!(s.strength >= 0.0 && s.strength <= 1.0)) throw UsageError("bloom strength must be in [0, 1]");
  if (!(s.threshold >= 0.0 && std::isfinite(s.threshold))) throw UsageError("bloom threshold must be >= 0");
  ImageRgbF halo = bloom_halo(bloom_bright_pass(image, s.threshold, s.threshold_space), s.levels);
  for (float& v : halo.rgb) v = static_cast<float>(s.strength * v);
  return halo;
}

ImageRgbF apply_bloom(const ImageRgbF& image, const BloomSettings& s) {
  if (!(s.strength >= 0.0 && s.strength <= 1.0)) throw UsageError("bloom strength must be in [0, 1]");
  if (!(s.threshold >= 0.0 && std::isfinite(s.threshold))) throw UsageError("bloom threshold must be >= 0");
  if (s.strength == 0.0) return image;
  const ImageRgbF bright = bloom_bright_pass(image, s.threshold, s.threshold_space);
  const ImageRgbF halo = bloom_halo(bright, s.levels);
  ImageRgbF out = image;
  for (std::size_t i = 0; i < out.rgb.size(); ++i)
    out.rgb[i] += static_cast<float>(s.strength * (double(halo.rgb[i]) - bright.rgb[i]));
  return out;
}

const ImageRgbF& expose_and_bloom(const ImageRgbF& film, double exposure_scale, const BloomSettings& bloom,
                                  ImageRgbF& storage, Mat3& to_input) {
  if (bloom.strength <= 0.0) {
    for (auto& row : to_input.m)
      for (double& v : row) v *= exposure_scale;
    return film;
  }
  storage = film;
  for (float& v : storage.rgb) v = std::isfinite(v) ? static_cast<float>(v * exposure_scale) : 0.0f;
  storage = apply_bloom(storage, bloom);
  return storage;
}

}  // namespace prism::display
