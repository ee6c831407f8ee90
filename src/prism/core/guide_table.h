#pragma once
// Guide tables (the "cutpoint" method of Chen and Asau 1974, "On generating random variates
// from an empirical distribution"): for sorted values, the last one at or below each of G
// equal steps of [0, 1], so that a search for the last value at or below u can start from
// entry ⌊u · G⌋ instead of from the whole range.
#include <cstddef>
#include <span>

namespace prism {

// guide[g] = the last index i < values.size() with values[i] ≤ g / guide.size(), compared
// in double (index 0 when none is), for non-decreasing values. With a power of two of
// entries, g / guide.size() is exact, so the entries bracket exactly what a full search for
// a float u finds.
template <class Index>
void fill_guide_table(std::span<const float> values, std::span<Index> guide) {
  std::size_t i = 0;
  for (std::size_t g = 0; g < guide.size(); ++g) {
    const double u = double(g) / double(guide.size());
    while (i + 1 < values.size() && double(values[i + 1]) <= u) ++i;
    guide[g] = static_cast<Index>(i);
  }
}

}  // namespace prism
