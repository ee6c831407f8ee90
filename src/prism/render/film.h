#pragma once
// Accumulation buffer: per-pixel sums of radiance and of its square (for a per-pixel
// variance estimate) in double precision, and per-pixel sample counts. Each pixel is only
// ever written by one thread at a time, in sample order, so sums are deterministic.
// Optional AOV sums (aov.h) are kept only for the AOVs a render asks for.
#include <cstdint>
#include <vector>

#include "prism/core/mat3.h"
#include "prism/core/vec.h"
#include "prism/render/aov.h"

namespace prism {

// Raw AOV state: sums over the pixel's samples (albedo, normal, depth over the samples
// that hit) and the number of samples that hit; for the variance AOV the beauty's cross
// sums (Σ xy, Σ xz, Σ yz of the film-space samples). Vectors of AOVs not in `set` are empty.
struct FilmAovSums {
  AovSet set;
  std::vector<Vec3d> albedo, normal;
  std::vector<Vec3d> cross;
  std::vector<double> depth;
  std::vector<std::uint32_t> depth_hits;
};

class Film {
 public:
  Film() = default;
  Film(int width, int height, AovSet aovs = {});
  // Restores a film from its raw state (checkpoints, merging). Sizes must match.
  Film(int width, int height, std::vector<Vec3d> sums, std::vector<Vec3d> sum_squares,
       std::vector<std::uint32_t> counts, FilmAovSums aovs = {});

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width_) * height_; }

  void add_sample(std::size_t pixel, const Vec3d& v) {
    sum_[pixel] += v;
    sum_squares_[pixel] += v * v;
    if (aov_.set.variance) aov_.cross[pixel] += Vec3d(v.x * v.y, v.x * v.z, v.y * v.z);
    ++count_[pixel];
  }

  // Adds the AOVs of the sample just given to add_sample (they share its count).
  void add_aov_sample(std::size_t pixel, const AovSample& a) {
    if (aov_.set.albedo) aov_.albedo[pixel] += Vec3d(a.albedo);
    if (aov_.set.normal) aov_.normal[pixel] += Vec3d(a.normal);
    if (aov_.set.depth && a.hit) {
      aov_.depth[pixel] += a.depth_scene_units;
      ++aov_.depth_hits[pixel];
    }
  }

  std::uint32_t sample_count(std::size_t pixel) const { return count_[pixel]; }
  // Mean radiance of the pixel (zero when it has no samples).
  Vec3d mean(std::size_t pixel) const;
  // Unbiased estimate of the variance of the pixel mean, per channel:
  // s² / n with s² the sample variance (needs n ≥ 2; zero otherwise).
  Vec3d variance_of_mean(std::size_t pixel) const;
  // The same for each channel of `film_to_output` · x (variance AOV only): row k of the
  // matrix applied to the sample covariance, m_kᵀ C m_k / n, exact for any linear output.
  Vec3d variance_of_mean(std::size_t pixel, const Mat3& film_to_output) const;

  const std::vector<Vec3d>& sums() const { return sum_; }
  const std::vector<Vec3d>& sum_squares() const { return sum_squares_; }
  const std::vector<std::uint32_t>& counts() const { return count_; }

  // Interleaved RGB means in single precision, row-major from the top-left pixel.
  std::vector<float> mean_rgb() const;

  const AovSet& aovs() const { return aov_.set; }
  const FilmAovSums& aov_sums() const { return aov_; }
  // Pixel means of the AOVs (zero without samples); only for AOVs in aovs().
  Vec3d albedo_mean(std::size_t pixel) const;
  Vec3d normal_mean(std::size_t pixel) const;
  // Mean over the samples that hit a surface; +inf when none did.
  double depth_mean(std::size_t pixel) const;
  // Fraction of the pixel's samples whose camera ray hit a surface (what depth averages
  // over; `prism merge` weights depth by it).
  double depth_coverage(std::size_t pixel) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<Vec3d> sum_, sum_squares_;
  std::vector<std::uint32_t> count_;
  FilmAovSums aov_;
};

}  // namespace prism
