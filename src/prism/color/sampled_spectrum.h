#pragma once
// The integrator's spectral "sample": N wavelengths drawn together with their pdfs, and a
// spectrum's values at those wavelengths (pbrt-v4 §4.6.2 layout; N is a template
// parameter so RGB (N = 3 channels) and spectral paths share one integrator source).
#include <array>
#include <cstddef>
#include <type_traits>

#include "prism/color/cie_1931.h"
#include "prism/core/vec.h"

namespace prism::color {

template <int N>
struct SampledWavelengths {
  static_assert(N >= 1);
  std::array<float, N> wavelength_nm{};
  // The density each λ_i is accounted with in the estimator (1/N) Σ f(λ_i)/pdf_i. For
  // strategies that mix techniques this is the balance-heuristic effective pdf, i.e. the
  // average of all techniques' densities at λ_i (see wavelength_sampling.h).
  std::array<float, N> pdf{};
};

// Four float lanes as one SSE register's type (a GCC vector extension).
typedef float SpectrumLanes4 __attribute__((vector_size(16)));

template <int N>
struct SampledSpectrum {
  static_assert(N >= 1);
  // Up to four channels (RGB, the default 4-wavelength tuple) are held as one 16-byte
  // vector, lanes past N zero. A 16-byte vector is one SSE register in the System V x86-64
  // ABI (class SSE + SSEUP, §3.2.3), so a spectrum passed to or returned from a function
  // that is not inlined travels in one register. As std::array<float, 4> it travelled as
  // two 8-byte halves, which callers put back together through the stack: two 8-byte
  // stores then a 16-byte load, which cannot be store-forwarded (a stall of the whole
  // load's latency on every such call; perf annotate of shade, docs/performance-design.md "Store-forwarding
  // stalls").
  // The operators also become one SSE instruction each. Wider tuples keep an array.
  static constexpr bool kVectorLanes = N <= 4;
  using Storage = std::conditional_t<kVectorLanes, SpectrumLanes4, std::array<float, N>>;
  Storage values{};

  constexpr SampledSpectrum() = default;
  constexpr explicit SampledSpectrum(float v) {
    for (int i = 0; i < N; ++i) values[i] = v;
  }
  constexpr explicit SampledSpectrum(const std::array<float, N>& a) {
    for (int i = 0; i < N; ++i) values[i] = a[static_cast<std::size_t>(i)];
  }
  constexpr float operator[](std::size_t i) const { return values[i]; }
  // A lane as a float lvalue. Clang binds no reference to a vector element (GCC does); both
  // let a vector's element type alias it, as SSE code that reads __m128 through float* relies on.
  float& operator[](std::size_t i) {
    if constexpr (kVectorLanes) return reinterpret_cast<float*>(&values)[i];
    else return values[i];
  }
  constexpr std::array<float, N> array() const {
    std::array<float, N> a{};
    for (int i = 0; i < N; ++i) a[static_cast<std::size_t>(i)] = values[i];
    return a;
  }

  constexpr SampledSpectrum& operator+=(const SampledSpectrum& o) {
    if constexpr (kVectorLanes) values += o.values;
    else for (int i = 0; i < N; ++i) values[i] += o.values[i];
    return *this;
  }
  constexpr SampledSpectrum& operator-=(const SampledSpectrum& o) {
    if constexpr (kVectorLanes) values -= o.values;
    else for (int i = 0; i < N; ++i) values[i] -= o.values[i];
    return *this;
  }
  constexpr SampledSpectrum& operator*=(const SampledSpectrum& o) {
    if constexpr (kVectorLanes) values *= o.values;
    else for (int i = 0; i < N; ++i) values[i] *= o.values[i];
    return *this;
  }
  constexpr SampledSpectrum& operator*=(float s) {
    if constexpr (kVectorLanes) values *= s;
    else for (float& v : values) v *= s;
    return *this;
  }
  // Division that maps x/0 to 0: a zero pdf marks a wavelength that carries no estimate
  // (and keeps the unused lanes 0).
  constexpr SampledSpectrum& operator/=(const SampledSpectrum& o) {
    if constexpr (kVectorLanes) values = o.values != 0.0f ? values / o.values : SpectrumLanes4{};
    else for (int i = 0; i < N; ++i) values[i] = o.values[i] != 0.0f ? values[i] / o.values[i] : 0.0f;
    return *this;
  }
  constexpr bool is_black() const {
    for (int i = 0; i < N; ++i)
      if (values[i] != 0.0f) return false;
    return true;
  }
  constexpr float average() const {
    float sum = 0.0f;
    for (int i = 0; i < N; ++i) sum += values[i];
    return sum / N;
  }
};

template <int N> constexpr SampledSpectrum<N> operator+(SampledSpectrum<N> a, const SampledSpectrum<N>& b) { return a += b; }
template <int N> constexpr SampledSpectrum<N> operator-(SampledSpectrum<N> a, const SampledSpectrum<N>& b) { return a -= b; }
template <int N> constexpr SampledSpectrum<N> operator*(SampledSpectrum<N> a, const SampledSpectrum<N>& b) { return a *= b; }
template <int N> constexpr SampledSpectrum<N> operator*(SampledSpectrum<N> a, float s) { return a *= s; }
template <int N> constexpr SampledSpectrum<N> operator*(float s, SampledSpectrum<N> a) { return a *= s; }
template <int N> constexpr SampledSpectrum<N> operator/(SampledSpectrum<N> a, const SampledSpectrum<N>& b) { return a /= b; }

// The values of a continuous spectrum (spectrum.h) at the sampled wavelengths.
template <int N, typename Spectrum>
SampledSpectrum<N> sample_spectrum(const Spectrum& s, const SampledWavelengths<N>& w) {
  SampledSpectrum<N> out;
  for (int i = 0; i < N; ++i) out[i] = static_cast<float>(s(w.wavelength_nm[i]));
  return out;
}

// One-sample Monte Carlo estimate of ∫ S(λ) (x̄, ȳ, z̄)(λ) dλ:
//   (1/N) Σ_i S(λ_i) x̄(λ_i) / p(λ_i),
// unbiased whenever each λ_i's marginal density averaged over i is the pdf stored with it
// (true for every strategy in wavelength_sampling.h). Accumulated in double.
template <int N>
Vec3d to_xyz(const SampledSpectrum<N>& s, const SampledWavelengths<N>& w) {
  const data::Table& cmf = detail::cie1931_table();
  Vec3d sum{};
  for (int i = 0; i < N; ++i) {
    if (w.pdf[i] == 0.0f) continue;
    sum += cie1931_xyz_bar(cmf, w.wavelength_nm[i]) * (double(s[i]) / double(w.pdf[i]));
  }
  return sum / double(N);
}

// Estimated luminance in nits of a spectral radiance sample (W·m⁻²·sr⁻¹·nm⁻¹).
template <int N>
double luminance_nits(const SampledSpectrum<N>& radiance, const SampledWavelengths<N>& w) {
  return kMaxLuminousEfficacyLmPerW * to_xyz(radiance, w).y;
}

}  // namespace prism::color
