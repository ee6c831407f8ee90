#pragma once
// Continuous spectra (functions of wavelength in nm) and their colorimetric integrals.
// Every spectrum type is a plain value with `double operator()(double wavelength_nm)`;
// code that takes "a spectrum" is a template over that, so no virtual call per sample
// (DESIGN.md: closed set, static dispatch).
#include <span>
#include <utility>
#include <vector>

#include "prism/color/cie_1931.h"
#include "prism/core/vec.h"

namespace prism::color {

struct ConstantSpectrum {
  double value = 0.0;
  double operator()(double) const { return value; }
};

// Tabulated at a constant step (1 nm for the CIE data), linearly interpolated, zero
// outside the table.
class DenseSpectrum {
 public:
  DenseSpectrum() = default;
  DenseSpectrum(double first_wavelength_nm, double step_nm, std::vector<double> values);
  // Samples any spectrum at 1 nm over [first_nm, last_nm].
  template <typename Spectrum>
  static DenseSpectrum sampled(const Spectrum& s, double first_nm = kVisibleMinNm,
                               double last_nm = kVisibleMaxNm) {
    std::vector<double> v;
    for (double nm = first_nm; nm <= last_nm + 1e-9; nm += 1.0) v.push_back(s(nm));
    return DenseSpectrum(first_nm, 1.0, std::move(v));
  }

  double operator()(double wavelength_nm) const;
  double first_wavelength_nm() const { return first_nm_; }
  double step_nm() const { return step_nm_; }
  std::span<const double> values() const { return values_; }

 private:
  double first_nm_ = 0.0;
  double step_nm_ = 1.0;
  std::vector<double> values_;
};

// Measured data at arbitrary, strictly increasing wavelengths (e.g. the Cornell box
// reflectances at 4 nm over 400–700 nm), linearly interpolated. Outside the measured
// range the end values are held: measured reflectances are routinely extrapolated that
// way rather than dropped to zero, which would darken the visible ends.
class PiecewiseLinearSpectrum {
 public:
  PiecewiseLinearSpectrum() = default;
  // Throws UsageError unless the sizes match, there are ≥ 1 points and λ increases.
  PiecewiseLinearSpectrum(std::vector<double> wavelengths_nm, std::vector<double> values);

  double operator()(double wavelength_nm) const;
  std::span<const double> wavelengths_nm() const { return wavelengths_nm_; }
  std::span<const double> values() const { return values_; }
  bool operator==(const PiecewiseLinearSpectrum&) const = default;

 private:
  std::vector<double> wavelengths_nm_;
  std::vector<double> values_;
};

// Planck's law: spectral radiance of a black body, W·m⁻²·sr⁻¹·nm⁻¹ (CODATA 2018 h, c, k).
double planck_radiance(double wavelength_nm, double temperature_k);

// A black body at `temperature_k`; `normalized` divides by the value at the peak
// wavelength (Wien: λ_max = b / T) so the spectrum peaks at exactly 1.
class BlackbodySpectrum {
 public:
  explicit BlackbodySpectrum(double temperature_k, bool normalized = false);
  double operator()(double wavelength_nm) const {
    return planck_radiance(wavelength_nm, temperature_k_) * scale_;
  }
  double temperature_k() const { return temperature_k_; }
  double peak_wavelength_nm() const;

 private:
  double temperature_k_;
  double scale_ = 1.0;
};

// ∫_a^b f(λ) dλ by the trapezoid rule at `step_nm` (1 nm by default: the CIE tables' own
// resolution, the rule the emission normalisation is defined with).
template <typename F>
double integrate_trapezoid(const F& f, double first_nm = kVisibleMinNm,
                           double last_nm = kVisibleMaxNm, double step_nm = 1.0) {
  const int steps = static_cast<int>((last_nm - first_nm) / step_nm + 0.5);
  double sum = 0.5 * (f(first_nm) + f(last_nm));
  for (int i = 1; i < steps; ++i) sum += f(first_nm + i * step_nm);
  return sum * step_nm;
}

// Unnormalised tristimulus values ∫ S(λ) (x̄, ȳ, z̄)(λ) dλ over the visible range (trapezoid,
// 1 nm). For a radiance spectrum in W·m⁻²·sr⁻¹·nm⁻¹, 683·Y is the luminance in nits.
// Colorimetric reference values (CIE 15:2004 §7.1) integrate the whole 360–830 nm table:
// pass those bounds to reproduce them.
template <typename Spectrum>
Vec3d spectrum_to_xyz(const Spectrum& s, int first_nm = static_cast<int>(kVisibleMinNm),
                      int last_nm = static_cast<int>(kVisibleMaxNm)) {
  Vec3d sum{};
  const int first = first_nm, last = last_nm;
  for (int nm = first; nm <= last; ++nm) {
    const double weight = (nm == first || nm == last) ? 0.5 : 1.0;
    sum += cie1931_xyz_bar(nm) * (weight * s(nm));
  }
  return sum;
}

// Luminance in cd/m² (nits) of a spectral radiance in W·m⁻²·sr⁻¹·nm⁻¹: 683 lm/W · ∫ L ȳ dλ.
template <typename Spectrum>
double luminance_nits(const Spectrum& radiance) {
  return kMaxLuminousEfficacyLmPerW * spectrum_to_xyz(radiance).y;
}

// XYZ of a reflectance under an illuminant, normalised so that the perfect white
// (reflectance 1) has Y = 1 (CIE 15:2004 §7.1 with k = 1/∫ S ȳ).
template <typename Reflectance, typename Illuminant>
Vec3d reflectance_to_xyz(const Reflectance& r, const Illuminant& illuminant) {
  const Vec3d xyz = spectrum_to_xyz([&](double nm) { return r(nm) * illuminant(nm); });
  return xyz / spectrum_to_xyz(illuminant).y;
}

}  // namespace prism::color
