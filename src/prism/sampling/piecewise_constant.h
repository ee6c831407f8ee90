#pragma once
// Piecewise-constant distributions: 1D over an interval and 2D over [0,1]² by the
// marginal/conditional construction (pbrt-v4 §A.5; the environment-map sampler of
// Pharr & Humphreys). The 1D form samples continuously (with the cell index and the
// remapped uniform) or discretely (with the probability mass).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "prism/core/branch_free.h"
#include "prism/core/vec.h"

namespace prism {

class PiecewiseConstant1D {
 public:
  PiecewiseConstant1D() = default;
  // f: N ≥ 1 non-negative, finite values over [min, max] (UsageError otherwise). A
  // function that is zero everywhere gives the uniform distribution.
  explicit PiecewiseConstant1D(std::span<const float> f, float min = 0.0f, float max = 1.0f);

  struct ContinuousSample {
    float x = 0.0f;    // in [min, max)
    float pdf = 0.0f;  // density with respect to x
    int index = 0;     // the cell x falls in
  };
  ContinuousSample sample_continuous(float u) const;

  struct DiscreteSample {
    int index = 0;
    float pmf = 0.0f;       // f[index] / Σ f
    float u_remapped = 0.0f; // u rescaled to [0,1) within the chosen cell, reusable
  };
  DiscreteSample sample_discrete(float u) const;

  float pdf(float x) const;  // 0 outside [min, max]
  // The cell pdf() reads at x ∈ [min, max] (the last cell for x = max).
  int cell(float x) const;
  // Builds a guide table (at least four 2-byte entries per cell) that makes sampling O(1)
  // instead of a binary search over the CDF; the cells found are the same. For small, hot
  // distributions (the wavelength lobes).
  void build_guide_table();
  // A coarse guide table (one 2-byte entry per kCellsPerCoarseGuideEntry cells, 1/16 of the
  // CDF's bytes) that brackets the cell, then a binary search inside the bracket: the same
  // cells, but the search touches a cache line or two of the CDF instead of one per halving
  // step. For big distributions that do not stay in the caches (environment-map rows).
  void build_coarse_guide_table();
  static constexpr int kCellsPerCoarseGuideEntry = 8;
  float pmf(int index) const;
  float cdf(int index) const;  // mass of the cells before `index` (index ∈ [0, N])
  int size() const { return size_; }
  // ∫ f over [min, max] (before any fallback to uniform).
  float integral() const { return integral_; }
  float min() const { return min_; }
  float max() const { return max_; }

 private:
  int find_cell(float u) const;
  // guide_[g] for `entries` entries: the last cell whose CDF is at or below g / entries.
  void fill_guide(std::size_t entries, bool coarse);

  int size_ = 0;            // N, the number of cells
  std::vector<float> cdf_;  // size N + 1, cdf_[0] = 0, cdf_[N] = 1
  // guide_[g]: the largest cell i with cdf_[i] ≤ g / guide_.size(), when built. 16 bits:
  // the wavelength lobes' three tables then fit the L1 cache beside the path state
  // (distributions of more than 65536 cells keep the binary search).
  std::vector<std::uint16_t> guide_;
  double guide_cells_ = 0.0;     // guide_.size() as a double (a size_t's conversion is several instructions)
  std::size_t last_guide_ = 0;   // guide_.size() − 1
  bool coarse_guide_ = false;    // built by build_coarse_guide_table: search between entries
  float integral_ = 0.0f;
  float min_ = 0.0f, max_ = 1.0f;
  float width_ = 1.0f;          // (max − min) / N
  float inverse_width_ = 1.0f;  // N / (max − min)
  float below_max_ = 1.0f;   // the largest float below max: samples stay in [min, max)
};

// Inline: the wavelength lobes sample through them once per wavelength of every path.
inline int PiecewiseConstant1D::cell(float x) const {
  return std::clamp(static_cast<int>((x - min_) * inverse_width_), 0, size() - 1);
}

inline int PiecewiseConstant1D::find_cell(float u) const {
  // Largest i with cdf_[i] ≤ u, skipping zero-width cells (they have f = 0).
  if (guide_cells_ > 0.0 && u >= 0.0f) {
    // guide_[g] ≤ the answer for every u ≥ g / size, so walking forward finds it.
    const std::size_t g = std::min(static_cast<std::size_t>(double(u) * guide_cells_), last_guide_);
    int i = static_cast<int>(guide_[g]);
    if (coarse_guide_) {
      // u < (g + 1) / guide size, so the answer is at most the next entry's cell (the last
      // cell past the last entry); the CDF is non-decreasing, so the cells of
      // cdf_[i + 1 .. hi] at or below u are a prefix, counted by the search.
      const int hi = g < last_guide_ ? static_cast<int>(guide_[g + 1]) : size() - 1;
      return i + static_cast<int>(upper_bound_index(cdf_.data() + i + 1, static_cast<std::size_t>(hi - i), u));
    }
    // The guide is fine enough that one step forward is all it takes wherever cells have
    // mass (build_guide_table): that step without a branch, whose outcome is a coin flip,
    // then the loop, which moves on only past cells of zero mass. cdf_ has size() + 1
    // entries, so cdf_[i + 1] is there even when i + 1 = size().
    i += static_cast<int>(i + 1 < size()) & static_cast<int>(cdf_[static_cast<std::size_t>(i) + 1] <= u);
    while (i + 1 < size() && cdf_[static_cast<std::size_t>(i) + 1] <= u) ++i;
    return i;
  }
  return std::clamp(static_cast<int>(upper_bound_index(cdf_.data(), cdf_.size(), u)) - 1, 0, size() - 1);
}

inline PiecewiseConstant1D::ContinuousSample PiecewiseConstant1D::sample_continuous(float u) const {
  const int i = find_cell(u);
  const float mass = cdf_[i + 1] - cdf_[i];
  float du = mass > 0.0f ? (u - cdf_[i]) / mass : 0.0f;
  du = std::clamp(du, 0.0f, std::nextafter(1.0f, 0.0f));
  ContinuousSample s;
  s.index = i;
  s.x = std::min(min_ + (i + du) * width_, below_max_);
  s.pdf = mass / width_;
  return s;
}

// Density over [0,1]² proportional to a grid of nu × nv cells, f row-major with u along
// rows: f[v * nu + u]. Sampling draws the row v from the marginal ∫ f du and then u from
// that row's conditional.
class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  PiecewiseConstant2D(std::span<const float> f, int nu, int nv);
  // The same, row by row: row_values(v, row) writes the nu values of row v (rows in order),
  // so the whole grid never exists at once (an environment map's would be 4 bytes per texel).
  PiecewiseConstant2D(int nu, int nv, const std::function<void(int v, std::span<float> row)>& row_values);

  struct Sample {
    Vec2f p;           // (u, v) in [0,1)²
    float pdf = 0.0f;  // density with respect to area in [0,1]²
  };
  Sample sample(Vec2f u) const;
  float pdf(Vec2f p) const;
  float integral() const { return marginal_.integral(); }

 private:
  std::vector<PiecewiseConstant1D> conditional_;
  PiecewiseConstant1D marginal_;
};

}  // namespace prism
