#pragma once
// A spectrum tabulated in float at 1 nm over the range wavelengths are sampled in
// (kVisibleMinNm–kVisibleMaxNm), evaluated at a path's N wavelengths by linear
// interpolation: one index and one lerp per wavelength. Spectra given as data (measured
// reflectances, illuminant SPDs; scene/spectral_inputs.h) are resampled to it once, so a
// path vertex never searches their own wavelength grid. At 1 nm the lerp reproduces the
// CIE tables (1 nm themselves) exactly at their points.
#include <algorithm>
#include <array>
#include <cstddef>

#include "prism/color/cie_1931.h"

namespace prism::color {

class VisibleSpectrumTable {
 public:
  static constexpr int kPoints = static_cast<int>(kVisibleMaxNm - kVisibleMinNm) + 1;

  VisibleSpectrumTable() = default;
  // `spectrum(λ)` (any callable of double nm) times `scale`, at λ = 380, 381, … 780 nm.
  template <class Spectrum>
  explicit VisibleSpectrumTable(const Spectrum& spectrum, double scale = 1.0) {
    for (int i = 0; i < kPoints; ++i)
      values_[static_cast<std::size_t>(i)] = static_cast<float>(scale * spectrum(kVisibleMinNm + i));
  }

  float operator()(float wavelength_nm) const {
    const float x = std::clamp(wavelength_nm - static_cast<float>(kVisibleMinNm), 0.0f,
                               static_cast<float>(kPoints - 1));
    const int i = std::min(static_cast<int>(x), kPoints - 2);
    const float t = x - static_cast<float>(i);
    const auto k = static_cast<std::size_t>(i);
    return values_[k] + t * (values_[k + 1] - values_[k]);
  }

  template <std::size_t N>
  std::array<float, N> evaluate(const std::array<float, N>& wavelength_nm) const {
    std::array<float, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = (*this)(wavelength_nm[i]);
    return out;
  }

 private:
  std::array<float, kPoints> values_{};
};

}  // namespace prism::color
