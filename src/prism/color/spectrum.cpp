// Dense, piecewise-linear and blackbody spectra.
#include "prism/color/spectrum.h"

#include <algorithm>
#include <cmath>

#include "prism/core/error.h"

namespace prism::color {

DenseSpectrum::DenseSpectrum(double first_wavelength_nm, double step_nm, std::vector<double> values)
    : first_nm_(first_wavelength_nm), step_nm_(step_nm), values_(std::move(values)) {
  if (!(step_nm > 0.0)) throw UsageError("dense spectrum step must be positive");
}

double DenseSpectrum::operator()(double wavelength_nm) const {
  if (values_.empty()) return 0.0;
  const double offset = (wavelength_nm - first_nm_) / step_nm_;
  const double last = static_cast<double>(values_.size() - 1);
  if (!(offset >= 0.0) || offset > last) return 0.0;
  if (values_.size() == 1) return values_[0];
  const auto i = std::min(static_cast<std::size_t>(offset), values_.size() - 2);
  const double t = offset - static_cast<double>(i);
  return values_[i] * (1.0 - t) + values_[i + 1] * t;
}

PiecewiseLinearSpectrum::PiecewiseLinearSpectrum(std::vector<double> wavelengths_nm,
                                                 std::vector<double> values)
    : wavelengths_nm_(std::move(wavelengths_nm)), values_(std::move(values)) {
  if (wavelengths_nm_.empty() || wavelengths_nm_.size() != values_.size())
    throw UsageError("piecewise-linear spectrum needs as many values as wavelengths (≥ 1)");
  for (std::size_t i = 1; i < wavelengths_nm_.size(); ++i)
    if (!(wavelengths_nm_[i] > wavelengths_nm_[i - 1]))
      throw UsageError("piecewise-linear spectrum wavelengths must increase strictly");
}

double PiecewiseLinearSpectrum::operator()(double wavelength_nm) const {
  if (wavelength_nm <= wavelengths_nm_.front()) return values_.front();
  if (wavelength_nm >= wavelengths_nm_.back()) return values_.back();
  const auto upper = std::upper_bound(wavelengths_nm_.begin(), wavelengths_nm_.end(), wavelength_nm);
  const auto i = static_cast<std::size_t>(upper - wavelengths_nm_.begin()) - 1;
  const double t = (wavelength_nm - wavelengths_nm_[i]) / (wavelengths_nm_[i + 1] - wavelengths_nm_[i]);
  return values_[i] * (1.0 - t) + values_[i + 1] * t;
}

double planck_radiance(double wavelength_nm, double temperature_k) {
  // CODATA 2018 exact SI constants.
  constexpr double h = 6.62607015e-34;  // J·s
  constexpr double c = 299792458.0;     // m/s
  constexpr double k = 1.380649e-23;    // J/K
  if (!(temperature_k > 0.0) || !(wavelength_nm > 0.0)) return 0.0;
  const double lambda_m = wavelength_nm * 1e-9;
  // B_λ(T) = 2hc² / λ⁵ / (exp(hc / λkT) − 1) in W·m⁻²·sr⁻¹·m⁻¹; × 1e-9 per nm.
  const double per_m =
      2.0 * h * c * c / std::pow(lambda_m, 5) / std::expm1(h * c / (lambda_m * k * temperature_k));
  return per_m * 1e-9;
}

BlackbodySpectrum::BlackbodySpectrum(double temperature_k, bool normalized)
    : temperature_k_(temperature_k) {
  if (!(temperature_k > 0.0) || !std::isfinite(temperature_k))
    throw UsageError("blackbody temperature must be a positive number of kelvin");
  if (normalized) scale_ = 1.0 / planck_radiance(peak_wavelength_nm(), temperature_k);
}

double BlackbodySpectrum::peak_wavelength_nm() const {
  constexpr double wien_b_m_k = 2.897771955e-3;  // Wien displacement constant, m·K (CODATA)
  return wien_b_m_k / temperature_k_ * 1e9;
}

}  // namespace prism::color
