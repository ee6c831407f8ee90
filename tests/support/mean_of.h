#pragma once
// The arithmetic mean of a buffer of floats, summed in double. Declared once so that the
// test files can share a translation unit (unity builds).
#include <vector>

namespace prism::test {

inline double mean_of(const std::vector<float>& v) {
  double s = 0.0;
  for (float x : v) s += x;
  return s / static_cast<double>(v.size());
}

}  // namespace prism::test
