#include "prism/sampling/piecewise_constant.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "prism/core/error.h"
#include "prism/core/guide_table.h"

namespace prism {

PiecewiseConstant1D::PiecewiseConstant1D(std::span<const float> f, float min, float max)
    : size_(static_cast<int>(f.size())), min_(min), max_(max) {
  if (f.empty()) throw UsageError("piecewise-constant distribution needs at least one value");
  if (f.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) - 1)
    throw UsageError("piecewise-constant distribution: too many values");
  if (!(max > min)) throw UsageError("piecewise-constant distribution needs max > min");
  for (float v : f)
    if (!(v >= 0.0f) || !std::isfinite(v))
      throw UsageError("piecewise-constant distribution needs finite, non-negative values");
  const int n = size();
  const double width = (double(max) - double(min)) / n;
  // Running sums in double so that long rows (e.g. 4k-wide environment maps) keep a
  // monotone, accurately normalised CDF in float. The values themselves are not kept:
  // the CDF says everything sampling and pdf() need (an environment map's distribution is
  // then 4 bytes per texel, not 8).
  std::vector<double> running(static_cast<std::size_t>(n) + 1, 0.0);
  for (int i = 0; i < n; ++i) running[i + 1] = running[i] + double(f[i]) * width;
  integral_ = static_cast<float>(running[n]);
  cdf_.resize(static_cast<std::size_t>(n) + 1);
  if (running[n] > 0.0) {
    for (int i = 0; i <= n; ++i) cdf_[i] = static_cast<float>(running[i] / running[n]);
  } else {
    for (int i = 0; i <= n; ++i) cdf_[i] = static_cast<float>(i) / n;  // all-zero: uniform fallback
  }
  cdf_[n] = 1.0f;
  width_ = (max_ - min_) / n;
  inverse_width_ = n / (max_ - min_);
  below_max_ = std::nextafter(max_, min_);
}

void PiecewiseConstant1D::build_guide_table() {
  // At least four cells per cell of the distribution, and at least 1/(smallest non-zero
  // mass), so that a guide cell holds at most one CDF step wherever cells have mass and
  // find_cell's forward walk takes at most one step there (capped at 2^20 entries).
  const int n = size();
  if (n > 65536) return;  // cell indices would not fit the 16-bit entries
  float smallest = 1.0f;
  for (int i = 0; i < n; ++i)
    if (cdf_[i + 1] > cdf_[i]) smallest = std::min(smallest, cdf_[i + 1] - cdf_[i]);
  const double cells = std::min(double(1 << 20), std::max(4.0 * n, std::ceil(1.0 / double(smallest)) + 1.0));
  fill_guide(static_cast<std::size_t>(cells), false);
}

void PiecewiseConstant1D::build_coarse_guide_table() {
  const int n = size();
  if (n > 65536) return;  // cell indices would not fit the 16-bit entries
  // A power of two of entries: g / size is then exact in double, so the comparisons in
  // fill_guide bracket exactly the cells find_cell's full search would find.
  fill_guide(std::bit_ceil(static_cast<std::size_t>((n + kCellsPerCoarseGuideEntry - 1) / kCellsPerCoarseGuideEntry)),
             true);
}

void PiecewiseConstant1D::fill_guide(std::size_t entries, bool coarse) {
  // Compared in double: a float u with g = ⌊u · size⌋ is ≥ g / size up to the product's
  // rounding, which is far below float's spacing, so cdf_[guide_[g]] ≤ u holds for it.
  guide_.resize(entries);
  fill_guide_table(std::span<const float>(cdf_.data(), static_cast<std::size_t>(size())), std::span(guide_));
  guide_cells_ = static_cast<double>(guide_.size());
  last_guide_ = guide_.size() - 1;
  coarse_guide_ = coarse;
}

float PiecewiseConstant1D::pmf(int index) const {
  if (index < 0 || index >= size()) return 0.0f;
  return cdf_[index + 1] - cdf_[index];
}

float PiecewiseConstant1D::cdf(int index) const { return cdf_[static_cast<std::size_t>(std::clamp(index, 0, size()))]; }

PiecewiseConstant1D::DiscreteSample PiecewiseConstant1D::sample_discrete(float u) const {
  const int i = find_cell(u);
  const float mass = cdf_[i + 1] - cdf_[i];
  DiscreteSample s;
  s.index = i;
  s.pmf = mass;
  s.u_remapped = mass > 0.0f ? std::clamp((u - cdf_[i]) / mass, 0.0f, std::nextafter(1.0f, 0.0f)) : 0.0f;
  return s;
}

float PiecewiseConstant1D::pdf(float x) const {
  if (x < min_ || x > max_) return 0.0f;
  return pmf(cell(x)) / width_;
}

namespace {

std::span<const float> checked_grid(std::span<const float> f, int nu, int nv) {
  if (nu < 1 || nv < 1 || f.size() != static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv))
    throw UsageError("piecewise-constant 2D distribution: size does not match nu × nv");
  return f;
}

}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> f, int nu, int nv)
    : PiecewiseConstant2D(nu, nv, [grid = checked_grid(f, nu, nv), nu](int v, std::span<float> row) {
        const auto first = grid.begin() + static_cast<std::ptrdiff_t>(v) * nu;
        std::copy(first, first + nu, row.begin());
      }) {}

PiecewiseConstant2D::PiecewiseConstant2D(int nu, int nv,
                                         const std::function<void(int v, std::span<float> row)>& row_values) {
  if (nu < 1 || nv < 1) throw UsageError("piecewise-constant 2D distribution: size does not match nu × nv");
  conditional_.reserve(static_cast<std::size_t>(nv));
  std::vector<float> row_integrals(static_cast<std::size_t>(nv));
  std::vector<float> row(static_cast<std::size_t>(nu));
  for (int v = 0; v < nv; ++v) {
    row_values(v, row);
    conditional_.emplace_back(row);
    conditional_.back().build_coarse_guide_table();
    row_integrals[v] = conditional_.back().integral();
  }
  marginal_ = PiecewiseConstant1D(row_integrals);
  marginal_.build_coarse_guide_table();
}

PiecewiseConstant2D::Sample PiecewiseConstant2D::sample(Vec2f u) const {
  const auto row = marginal_.sample_continuous(u.y);
  const auto col = conditional_[row.index].sample_continuous(u.x);
  // p(u, v) = p(v) p(u | v).
  return {Vec2f(col.x, row.x), row.pdf * col.pdf};
}

float PiecewiseConstant2D::pdf(Vec2f p) const {
  if (p.x < 0.0f || p.x > 1.0f || p.y < 0.0f || p.y > 1.0f) return 0.0f;
  const int nv = static_cast<int>(conditional_.size());
  const int v = std::clamp(static_cast<int>(p.y * nv), 0, nv - 1);
  return marginal_.pdf(p.y) * conditional_[v].pdf(p.x);
}

}  // namespace prism
