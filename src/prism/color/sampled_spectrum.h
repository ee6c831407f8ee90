#pragma once
// The integrator's spectral "sample": N wavelengths drawn together with their pdfs, and a
// spectrum's values at those wavelengths (pbrt-v4 §4.6.2 layout; N is a template
// parameter so RGB (N = 3 channels) and spectral paths share one integrator source).
#include <array>
#include <cstddef>

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

template <int N>
struct SampledSpectrum {
  static_assert(N >= 1);
  std::array<float, N> values{};

  constexpr SampledSpectrum() = default;
  constexpr explicit SampledSpectrum(float v) { values.fill(v); }
  constexpr float operator[](std::size_t i) const { return values[i]; }
  constexpr float& operator[](std::size_t i) { return values[i]; }

  constexpr SampledSpectrum& operator+=(const SampledSpectrum& o) {
    for (int i = 0; i < N; ++i) values[i] += o.values[i];
    return *this;
  }
  constexpr SampledSpectrum& operator-=(const SampledSpectrum& o) {
    for (int i = 0; i < N; ++i) values[i] -= o.values[i];
    return *this;
  }
  constexpr SampledSpectrum& operator*=(const SampledSpectrum& o) {
    for (int i = 0; i < N; ++i) values[i] *= o.values[i];
    return *this;
  }
  constexpr SampledSpectrum& operator*=(float s) {
    for (float& v : values) v *= s;
    return *this;
  }
  // Division that maps x/0 to 0: a zero pdf marks a wavelength that carries no estimate.
  constexpr SampledSpectrum& operator/=(const SampledSpectrum& o) {
    for (int i = 0; i < N; ++i) values[i] = o.values[i] != 0.0f ? values[i] / o.values[i] : 0.0f;
    return *this;
  }
  constexpr bool is_black() const {
    for (float v : values)
      if (v != 0.0f) return false;
    return true;
  }
  constexpr float average() const {
    float sum = 0.0f;
    for (float v : values) sum += v;
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
  Vec3d sum{};
  for (int i = 0; i < N; ++i) {
    if (w.pdf[i] == 0.0f) continue;
    sum += cie1931_xyz_bar(w.wavelength_nm[i]) * (double(s[i]) / double(w.pdf[i]));
  }
  return sum / double(N);
}

// Estimated luminance in nits of a spectral radiance sample (W·m⁻²·sr⁻¹·nm⁻¹).
template <int N>
double luminance_nits(const SampledSpectrum<N>& radiance, const SampledWavelengths<N>& w) {
  return kMaxLuminousEfficacyLmPerW * to_xyz(radiance, w).y;
}

}  // namespace prism::color
