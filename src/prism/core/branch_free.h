#pragma once
// Choices whose outcome is a coin flip, made as data instead of control flow.
//
// Sampling code is full of them: which wedge of the concentric map a point falls in,
// which half of the square Heitz's triangle map shears, which of two lights a number
// selects. As branches they are mispredicted about half the time (≈ 15–20 cycles each on
// a current core, several per path vertex), and GCC compiles a plain `c ? a : b` on
// floats to a branch when it targets baseline x86-64 (SSE2 has no blend instruction).
// Here the comparison yields a mask in an SSE register (cmpltss/cmpltsd) that picks the
// value with and/andnot/or, and the binary search moves its base by a masked step, so the
// compiler sees no condition to branch on. Results are exactly those of the branching
// forms.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prism {

// a where x < y, else b (b also when either is NaN, as with `x < y ? a : b`).
inline float select_less(float x, float y, float a, float b) {
#if defined(__SSE2__)
  const __m128 mask = _mm_cmplt_ss(_mm_set_ss(x), _mm_set_ss(y));
  return _mm_cvtss_f32(_mm_or_ps(_mm_and_ps(mask, _mm_set_ss(a)), _mm_andnot_ps(mask, _mm_set_ss(b))));
#else
  return x < y ? a : b;
#endif
}

inline double select_less(double x, double y, double a, double b) {
#if defined(__SSE2__)
  const __m128d mask = _mm_cmplt_sd(_mm_set_sd(x), _mm_set_sd(y));
  return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(mask, _mm_set_sd(a)), _mm_andnot_pd(mask, _mm_set_sd(b))));
#else
  return x < y ? a : b;
#endif
}

// value where keep, else +0: the float's bits masked by the condition (a NaN or an
// infinity that is not kept becomes +0 too).
inline float keep_if(bool keep, float value) {
  return std::bit_cast<float>(std::bit_cast<std::uint32_t>(value) & (std::uint32_t{0} - static_cast<std::uint32_t>(keep)));
}

// a where take, else b, for any trivially copyable value a word at a time: its bits are one
// or the other's (for spectra: a running sum that takes a term or not).
template <class T>
T select_bits(bool take, const T& a, const T& b) {
  static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % sizeof(std::uint32_t) == 0);
  using Words = std::array<std::uint32_t, sizeof(T) / sizeof(std::uint32_t)>;
  Words x = std::bit_cast<Words>(a);
  const Words y = std::bit_cast<Words>(b);
  const std::uint32_t mask = std::uint32_t{0} - static_cast<std::uint32_t>(take);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (x[i] & mask) | (y[i] & ~mask);
  return std::bit_cast<T>(x);
}

// std::upper_bound's answer as an index: the first of the sorted values[0, n) that is
// greater than x, n when there is none (also for a NaN x, as std::upper_bound, whose test
// is x < value). Halving with a masked step (Khuong & Morin 2017, "Array layouts for
// comparison-based searching", the branch-free binary search): the answer stays in
// [base, base + n]; each step keeps the upper half when its first element's
// predecessor is ≤ x. The same log2(n) comparisons, none of them a branch.
inline std::size_t upper_bound_index(const float* values, std::size_t n, float x) {
  if (n == 0) return 0;
  std::size_t base = 0;
  while (n > 1) {
    const std::size_t half = n / 2;
    // values[base + half - 1] ≤ x: the answer is past it, so at base + half or later.
    base += (std::size_t{0} - static_cast<std::size_t>(!(x < values[base + half - 1]))) & half;
    n -= half;
  }
  return base + static_cast<std::size_t>(!(x < values[base]));
}

}  // namespace prism
