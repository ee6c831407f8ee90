#pragma once
// Natural logarithms of four floats at once, for the hot loops that need several (cosh
// wavelength sampling takes one per wavelength): one SSE2 instruction stream instead of four
// libm calls, which the compiler can neither inline nor overlap.
//
// For x = m · 2^e with m ∈ [√½, √2): ln x = e ln 2 + ln m, and with s = (m − 1)/(m + 1)
// (|s| ≤ 3 − 2√2 ≈ 0.1716), ln m = 2 atanh(s) = 2s (1 + s²/3 + s⁴/5 + s⁶/7 + s⁸/9 + …), the
// series of atanh (Abramowitz & Stegun 4.5.64 with 4.6.22). The terms left out sum to
// less than 2|s|¹¹/(11(1 − s²)) < 7e-10, far under float's resolution; what is left is
// float rounding (tests/core/log4_test.cpp bounds it against double std::log).
//
// Positive, finite, normal inputs only (the callers' ratios lie in [0.05, 40]): zero,
// negatives, subnormals, infinities and NaN are not handled.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "prism/core/target_region.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prism {

namespace log4_detail {
inline constexpr float kLn2 = 0.693147180559945309f;
inline constexpr float kSqrtHalf = 0.707106781186547524f;
}  // namespace log4_detail

// Lane by lane, the same operations in the same order as log4's SSE2 path (so both give the
// same bits): the fallback where SSE2 is missing, and the tests' check of the vector code.
inline std::array<float, 4> log4_lanewise(const std::array<float, 4>& x) {
  using namespace log4_detail;
  std::array<float, 4> out;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto bits = std::bit_cast<std::uint32_t>(x[i]);
    int exponent = static_cast<int>(bits >> 23) - 127;
    float m = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);
    if (m >= 2.0f * kSqrtHalf) m *= 0.5f, ++exponent;
    const float s = (m - 1.0f) / (m + 1.0f), z = s * s;
    float series = z * (1.0f / 9.0f) + 1.0f / 7.0f;
    series = z * series + 1.0f / 5.0f;
    series = z * series + 1.0f / 3.0f;
    series = z * series + 1.0f;
    out[i] = static_cast<float>(exponent) * kLn2 + (s + s) * series;
  }
  return out;
}

#if defined(__SSE2__)
// log4 on a register, for callers whose numbers already live in one.
inline __m128 log4_ps(__m128 x) {
  using namespace log4_detail;
  const __m128i bits = _mm_castps_si128(x);
  // The exponent e and the mantissa m ∈ [1, 2) (the exponent field set to 127's).
  __m128i exponent = _mm_sub_epi32(_mm_srli_epi32(bits, 23), _mm_set1_epi32(127));
  __m128 m = _mm_castsi128_ps(
      _mm_or_si128(_mm_and_si128(bits, _mm_set1_epi32(0x007fffff)), _mm_set1_epi32(0x3f800000)));
  // m ≥ √2: m/2 and e + 1, so that m ∈ [√½, √2) (halving is exact).
  const __m128 high = _mm_cmpge_ps(m, _mm_set1_ps(2.0f * kSqrtHalf));
  m = _mm_or_ps(_mm_and_ps(high, _mm_mul_ps(m, _mm_set1_ps(0.5f))), _mm_andnot_ps(high, m));
  exponent = _mm_sub_epi32(exponent, _mm_castps_si128(high));  // the mask is −1 where high
  const __m128 one = _mm_set1_ps(1.0f);
  const __m128 s = _mm_div_ps(_mm_sub_ps(m, one), _mm_add_ps(m, one));
  const __m128 z = _mm_mul_ps(s, s);
  __m128 series = _mm_add_ps(_mm_mul_ps(z, _mm_set1_ps(1.0f / 9.0f)), _mm_set1_ps(1.0f / 7.0f));
  series = _mm_add_ps(_mm_mul_ps(z, series), _mm_set1_ps(1.0f / 5.0f));
  series = _mm_add_ps(_mm_mul_ps(z, series), _mm_set1_ps(1.0f / 3.0f));
  series = _mm_add_ps(_mm_mul_ps(z, series), one);
  const __m128 ln_m = _mm_mul_ps(_mm_add_ps(s, s), series);
  return _mm_add_ps(_mm_mul_ps(_mm_cvtepi32_ps(exponent), _mm_set1_ps(kLn2)), ln_m);
}
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
PRISM_TARGET_REGION_BEGIN("avx2")
// log4_ps in eight lanes, for AVX2 code (a caller that has checked the processor): the same
// operations in the same order, so the same bits (log4_test).
inline __m256 log8_ps(__m256 x) {
  using namespace log4_detail;
  const __m256i bits = _mm256_castps_si256(x);
  __m256i exponent = _mm256_sub_epi32(_mm256_srli_epi32(bits, 23), _mm256_set1_epi32(127));
  __m256 m = _mm256_castsi256_ps(
      _mm256_or_si256(_mm256_and_si256(bits, _mm256_set1_epi32(0x007fffff)), _mm256_set1_epi32(0x3f800000)));
  const __m256 high = _mm256_cmp_ps(m, _mm256_set1_ps(2.0f * kSqrtHalf), _CMP_GE_OS);
  m = _mm256_or_ps(_mm256_and_ps(high, _mm256_mul_ps(m, _mm256_set1_ps(0.5f))), _mm256_andnot_ps(high, m));
  exponent = _mm256_sub_epi32(exponent, _mm256_castps_si256(high));
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256 s = _mm256_div_ps(_mm256_sub_ps(m, one), _mm256_add_ps(m, one));
  const __m256 z = _mm256_mul_ps(s, s);
  __m256 series = _mm256_add_ps(_mm256_mul_ps(z, _mm256_set1_ps(1.0f / 9.0f)), _mm256_set1_ps(1.0f / 7.0f));
  series = _mm256_add_ps(_mm256_mul_ps(z, series), _mm256_set1_ps(1.0f / 5.0f));
  series = _mm256_add_ps(_mm256_mul_ps(z, series), _mm256_set1_ps(1.0f / 3.0f));
  series = _mm256_add_ps(_mm256_mul_ps(z, series), one);
  const __m256 ln_m = _mm256_mul_ps(_mm256_add_ps(s, s), series);
  return _mm256_add_ps(_mm256_mul_ps(_mm256_cvtepi32_ps(exponent), _mm256_set1_ps(kLn2)), ln_m);
}

PRISM_TARGET_REGION_END
#endif

inline std::array<float, 4> log4(const std::array<float, 4>& x) {
#if defined(__SSE2__)
  std::array<float, 4> out;
  _mm_storeu_ps(out.data(), log4_ps(_mm_loadu_ps(x.data())));
  return out;
#else
  return log4_lanewise(x);
#endif
}

}  // namespace prism
