#pragma once
// Accumulation buffer: per-pixel sums of radiance and of its square (for a per-pixel
// variance estimate) in double precision, and per-pixel sample counts. Each pixel is only
// ever written by one thread at a time, in sample order, so sums are deterministic.
#include <cstdint>
#include <vector>

#include "prism/core/vec.h"

namespace prism {

class Film {
 public:
  Film() = default;
  Film(int width, int height);
  // Restores a film from its raw state (checkpoints, merging). Sizes must match.
  Film(int width, int height, std::vector<Vec3d> sums, std::vector<Vec3d> sum_squares,
       std::vector<std::uint32_t> counts);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width_) * height_; }

  void add_sample(std::size_t pixel, const Vec3d& v) {
    sum_[pixel] += v;
    sum_squares_[pixel] += v * v;
    ++count_[pixel];
  }

  std::uint32_t sample_count(std::size_t pixel) const { return count_[pixel]; }
  // Mean radiance of the pixel (zero when it has no samples).
  Vec3d mean(std::size_t pixel) const;
  // Unbiased estimate of the variance of the pixel mean, per channel:
  // s² / n with s² the sample variance (needs n ≥ 2; zero otherwise).
  Vec3d variance_of_mean(std::size_t pixel) const;

  const std::vector<Vec3d>& sums() const { return sum_; }
  const std::vector<Vec3d>& sum_squares() const { return sum_squares_; }
  const std::vector<std::uint32_t>& counts() const { return count_; }

  // Interleaved RGB means in single precision, row-major from the top-left pixel.
  std::vector<float> mean_rgb() const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<Vec3d> sum_, sum_squares_;
  std::vector<std::uint32_t> count_;
};

}  // namespace prism
