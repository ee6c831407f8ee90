#pragma once
// The Jakob & Hanika 2019 spectrum model ("A Low-Dimensional Function Space for Efficient
// Spectral Upsampling", Computer Graphics Forum 38(2)): s(λ) = S(c₀λ² + c₁λ + c₂) with the
// sigmoid S(x) = ½ + x / (2√(1 + x²)) (paper eq. 3), λ in nm. Smooth, bounded to [0, 1],
// and three numbers per colour.
#include <array>
#include <cmath>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prism::color {

inline double sigmoid_jakob_hanika(double x) {
  if (std::isinf(x)) return x > 0 ? 1.0 : 0.0;
  return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
}

struct SigmoidPolynomial {
  double c0 = 0.0, c1 = 0.0, c2 = 0.0;  // coefficients of λ², λ, 1 with λ in nm

  double operator()(double wavelength_nm) const {
    return sigmoid_jakob_hanika(std::fma(std::fma(c0, wavelength_nm, c1), wavelength_nm, c2));
  }
  // The constant spectrum v ∈ [0, 1] (v = 0 and 1 need infinite c₂): S⁻¹(v).
  static SigmoidPolynomial constant(double v) {
    if (v <= 0.0) return {0.0, 0.0, -INFINITY};
    if (v >= 1.0) return {0.0, 0.0, INFINITY};
    return {0.0, 0.0, (v - 0.5) / std::sqrt(v * (1.0 - v))};
  }
};

// S(x) in single precision, for the renderer's hot path. Written as
//   min(S, 1 − S) = 1 / (2r(r + |x|)),  r = √(1 + x²)
// (from (r + x)(r − x) = 1), which has no cancellation: ½ + x/(2r) in float loses every
// digit below float's step at ½ (6e-8) on the dark side, where reflectances of saturated
// colours live. No branch: x = ±∞ (the constant spectra 0 and 1) gives r = ∞ and a tail of
// exactly 0; NaN stays NaN.
inline float sigmoid_jakob_hanika_float(float x) {
  const float r = std::sqrt(1.0f + x * x);
  const float tail = 1.0f / ((r + r) * (r + std::abs(x)));
  return x < 0.0f ? tail : 1.0f - tail;
}

// s(λ_i) for N wavelengths at once, scaled by `scale`: the polynomial in double (its terms
// reach ±10³ for saturated colours and cancel to |x| of a few units; float would lose four
// digits there), the sigmoid in float, four wavelengths per SSE instruction where the
// target has SSE2 (every x86-64), with the same operations in the same order as
// sigmoid_jakob_hanika_float, so both give identical bits. Within 1e-6 relative of
// operator() (jakob_hanika_test).
// Always inlined: called, a std::array<float, 4> comes back in two registers of 8 bytes
// each (the x86-64 System V ABI's SSE eightbytes), which GCC 12 stored to the stack apart
// and read back as one 16-byte load, a load the store buffer cannot forward (37 % of
// untextured_emission's samples on the Cornell box; docs/performance-design.md "Store-forwarding stalls").
template <std::size_t N>
[[gnu::always_inline]] inline std::array<float, N> evaluate_sigmoid_polynomial(
    const SigmoidPolynomial& c, const std::array<float, N>& wavelength_nm, float scale = 1.0f) {
  constexpr std::size_t kPadded = (N + 3) / 4 * 4;
  alignas(16) std::array<float, kPadded> x{};
  for (std::size_t i = 0; i < N; ++i) {
    const double nm = wavelength_nm[i];
    x[i] = static_cast<float>((c.c0 * nm + c.c1) * nm + c.c2);
  }
  alignas(16) std::array<float, kPadded> s{};
#if defined(__SSE2__)
  const __m128 one = _mm_set1_ps(1.0f), scale4 = _mm_set1_ps(scale), sign = _mm_set1_ps(-0.0f);
  for (std::size_t i = 0; i < kPadded; i += 4) {
    const __m128 v = _mm_load_ps(&x[i]);
    const __m128 r = _mm_sqrt_ps(_mm_add_ps(one, _mm_mul_ps(v, v)));
    const __m128 tail = _mm_div_ps(one, _mm_mul_ps(_mm_add_ps(r, r), _mm_add_ps(r, _mm_andnot_ps(sign, v))));
    const __m128 negative = _mm_cmplt_ps(v, _mm_setzero_ps());
    const __m128 sigmoid = _mm_or_ps(_mm_and_ps(negative, tail), _mm_andnot_ps(negative, _mm_sub_ps(one, tail)));
    _mm_store_ps(&s[i], _mm_mul_ps(scale4, sigmoid));
  }
#else
  for (std::size_t i = 0; i < N; ++i) s[i] = scale * sigmoid_jakob_hanika_float(x[i]);
#endif
  std::array<float, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = s[i];
  return out;
}

}  // namespace prism::color
