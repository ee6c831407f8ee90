#pragma once
// Means and their estimated variances over blocks of a film, for tests that compare
// renders within noise bounds derived from the film's own per-pixel variance; and the
// bitwise comparison of two films.
#include "prism/render/film.h"

namespace prism::test {

struct BlockEstimate {
  Vec3d mean;
  Vec3d variance;  // of the mean: pixels are independent
};

inline BlockEstimate block_estimate(const Film& film, int x0, int y0, int x1, int y1) {
  BlockEstimate e;
  double n = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * film.width() + x;
      e.mean += film.mean(p);
      e.variance += film.variance_of_mean(p);
      n += 1.0;
    }
  e.mean /= n;
  e.variance /= n * n;
  return e;
}

// Two films hold the same sums, squares and counts, bit for bit: the same image, and the
// same image to every later sample added.
inline bool films_identical(const Film& a, const Film& b) {
  return a.sums() == b.sums() && a.sum_squares() == b.sum_squares() && a.counts() == b.counts();
}

}  // namespace prism::test
