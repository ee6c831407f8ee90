#include "prism/display/resampling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "prism/core/error.h"

namespace prism::display {

ImageRgbF upscale_bilinear(const ImageRgbF& in, int width, int height) {
  if (width < 1 || height < 1 || in.width < 1 || in.height < 1)
    throw UsageError("cannot resample an image to or from " + std::to_string(width) + "x" + std::to_string(height));
  ImageRgbF out{width, height, std::vector<float>(3u * width * height)};
  const double sx = double(in.width) / width, sy = double(in.height) / height;
  for (int y = 0; y < height; ++y) {
    // Source coordinate of this output centre, in source pixel-centre units.
    const double fy = std::clamp((y + 0.5) * sy - 0.5, 0.0, double(in.height - 1));
    const int y0 = static_cast<int>(fy), y1 = std::min(y0 + 1, in.height - 1);
    const double ty = fy - y0;
    for (int x = 0; x < width; ++x) {
      const double fx = std::clamp((x + 0.5) * sx - 0.5, 0.0, double(in.width - 1));
      const int x0 = static_cast<int>(fx), x1 = std::min(x0 + 1, in.width - 1);
      const double tx = fx - x0;
      for (int c = 0; c < 3; ++c) {
        auto at = [&](int xx, int yy) { return double(in.rgb[3 * (std::size_t(yy) * in.width + xx) + c]); };
        const double top = at(x0, y0) + tx * (at(x1, y0) - at(x0, y0));
        const double bottom = at(x0, y1) + tx * (at(x1, y1) - at(x0, y1));
        out.rgb[3 * (std::size_t(y) * width + x) + c] = static_cast<float>(top + ty * (bottom - top));
      }
    }
  }
  return out;
}

int upscaled_size(int render_size, double render_scale) {
  if (!(render_scale > 0.0 && render_scale <= 1.0))
    throw UsageError("render scale must be in (0, 1], got " + std::to_string(render_scale));
  return std::max(1, static_cast<int>(std::lround(render_size / render_scale)));
}

ImageRgbF downsample_box2(const ImageRgbF& in) {
  const int w = std::max(1, in.width / 2), h = std::max(1, in.height / 2);
  ImageRgbF out{w, h, std::vector<float>(3u * w * h, 0.0f)};
  std::vector<double> sum(3u * w * h, 0.0);
  std::vector<int> count(std::size_t(w) * h, 0);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      const std::size_t o = std::size_t(std::min(y / 2, h - 1)) * w + std::min(x / 2, w - 1);
      ++count[o];
      for (int c = 0; c < 3; ++c) sum[3 * o + c] += in.rgb[3 * (std::size_t(y) * in.width + x) + c];
    }
  // Each block's sum spread over its area in the coarse grid (4 fine pixels per coarse one),
  // so that sum(out) × 4 = sum(in) even for odd sizes.
  for (std::size_t o = 0; o < count.size(); ++o)
    for (int c = 0; c < 3; ++c) out.rgb[3 * o + c] = static_cast<float>(sum[3 * o + c] / 4.0);
  return out;
}

}  // namespace prism::display
