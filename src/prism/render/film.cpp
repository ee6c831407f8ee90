#include "prism/render/film.h"

#include <algorithm>
#include <limits>

#include "prism/core/error.h"

namespace prism {

namespace {

bool aov_sizes_match(const FilmAovSums& a, std::size_t pixels) {
  const auto size_ok = [pixels](bool on, std::size_t size) { return size == (on ? pixels : 0u); };
  return size_ok(a.set.albedo, a.albedo.size()) && size_ok(a.set.normal, a.normal.size()) &&
         size_ok(a.set.depth, a.depth.size()) && size_ok(a.set.depth, a.depth_hits.size()) &&
         size_ok(a.set.variance, a.cross.size());
}

}  // namespace

Film::Film(int width, int height, AovSet aovs)
    : width_(width), height_(height), sum_(pixel_count()), sum_squares_(pixel_count()),
      count_(pixel_count(), 0u) {
  aov_.set = aovs;
  if (aovs.albedo) aov_.albedo.resize(pixel_count());
  if (aovs.normal) aov_.normal.resize(pixel_count());
  if (aovs.variance) aov_.cross.resize(pixel_count());
  if (aovs.depth) {
    aov_.depth.resize(pixel_count(), 0.0);
    aov_.depth_hits.resize(pixel_count(), 0u);
  }
}

Film::Film(int width, int height, std::vector<Vec3d> sums, std::vector<Vec3d> sum_squares,
           std::vector<std::uint32_t> counts, FilmAovSums aovs)
    : width_(width), height_(height), sum_(std::move(sums)), sum_squares_(std::move(sum_squares)),
      count_(std::move(counts)), aov_(std::move(aovs)) {
  if (width < 0 || height < 0 || sum_.size() != pixel_count() || sum_squares_.size() != pixel_count() ||
      count_.size() != pixel_count() || !aov_sizes_match(aov_, pixel_count()))
    throw Error("film state does not match its size");
}

Vec3d Film::mean(std::size_t pixel) const {
  const std::uint32_t n = count_[pixel];
  return n > 0 ? sum_[pixel] / static_cast<double>(n) : Vec3d(0.0);
}

Vec3d Film::variance_of_mean(std::size_t pixel) const {
  const double n = count_[pixel];
  if (n < 2.0) return Vec3d(0.0);
  const Vec3d m = sum_[pixel] / n;
  Vec3d s2 = (sum_squares_[pixel] - m * m * n) / (n - 1.0);
  s2 = max(s2, Vec3d(0.0));
  return s2 / n;
}

Vec3d Film::variance_of_mean(std::size_t pixel, const Mat3& m) const {
  const double n = count_[pixel];
  if (n < 2.0) return Vec3d(0.0);
  // Sample covariance C = (Σ x xᵀ − n x̄ x̄ᵀ) / (n − 1), from the squares and cross sums.
  const Vec3d mean = sum_[pixel] / n, sq = sum_squares_[pixel], cr = aov_.cross[pixel];
  const double second[3][3] = {{sq.x, cr.x, cr.y}, {cr.x, sq.y, cr.z}, {cr.y, cr.z, sq.z}};
  Vec3d out;
  for (int k = 0; k < 3; ++k) {
    double q = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) q += m(k, i) * m(k, j) * (second[i][j] - n * mean[i] * mean[j]);
    out[k] = std::max(0.0, q / (n - 1.0)) / n;
  }
  return out;
}

Vec3d Film::albedo_mean(std::size_t pixel) const {
  const std::uint32_t n = count_[pixel];
  return n > 0 ? aov_.albedo[pixel] / static_cast<double>(n) : Vec3d(0.0);
}

Vec3d Film::normal_mean(std::size_t pixel) const {
  const std::uint32_t n = count_[pixel];
  return n > 0 ? aov_.normal[pixel] / static_cast<double>(n) : Vec3d(0.0);
}

double Film::depth_mean(std::size_t pixel) const {
  const std::uint32_t hits = aov_.depth_hits[pixel];
  return hits > 0 ? aov_.depth[pixel] / hits : std::numeric_limits<double>::infinity();
}

double Film::depth_coverage(std::size_t pixel) const {
  const std::uint32_t n = count_[pixel];
  return n > 0 ? static_cast<double>(aov_.depth_hits[pixel]) / n : 0.0;
}

std::vector<float> Film::mean_rgb() const {
  std::vector<float> rgb(3 * pixel_count());
  for (std::size_t i = 0; i < pixel_count(); ++i) {
    const Vec3d m = mean(i);
    rgb[3 * i + 0] = static_cast<float>(m.x);
    rgb[3 * i + 1] = static_cast<float>(m.y);
    rgb[3 * i + 2] = static_cast<float>(m.z);
  }
  return rgb;
}

}  // namespace prism
