#pragma once
// Piecewise-constant distributions: 1D over an interval and 2D over [0,1]² by the
// marginal/conditional construction (pbrt-v4 §A.5; the environment-map sampler of
// Pharr & Humphreys). The 1D form samples continuously (with the cell index and the
// remapped uniform) or discretely (with the probability mass).
#include <span>
#include <vector>

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
  float pmf(int index) const;
  int size() const { return static_cast<int>(f_.size()); }
  // ∫ f over [min, max] (before any fallback to uniform).
  float integral() const { return integral_; }
  float min() const { return min_; }
  float max() const { return max_; }

 private:
  int find_cell(float u) const;

  std::vector<float> f_;
  std::vector<float> cdf_;  // size N + 1, cdf_[0] = 0, cdf_[N] = 1
  float integral_ = 0.0f;
  float min_ = 0.0f, max_ = 1.0f;
};

// Density over [0,1]² proportional to a grid of nu × nv cells, f row-major with u along
// rows: f[v * nu + u]. Sampling draws the row v from the marginal ∫ f du and then u from
// that row's conditional.
class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  PiecewiseConstant2D(std::span<const float> f, int nu, int nv);

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
