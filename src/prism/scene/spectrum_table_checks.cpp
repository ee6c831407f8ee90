#include "prism/scene/spectrum_table_checks.h"

#include <cmath>

#include <fmt/format.h>

namespace prism {

std::string spectrum_table_problem(std::span<const double> nm, std::span<const double> values, double max_value) {
  if (nm.size() != values.size()) return fmt::format("{} wavelengths but {} values", nm.size(), values.size());
  if (nm.size() < 2) return "a tabulated spectrum needs at least 2 points";
  if (nm.size() > kMaxSpectrumPoints) return fmt::format("more than {} points", kMaxSpectrumPoints);
  for (std::size_t i = 0; i < nm.size(); ++i) {
    if (!(nm[i] >= kMinSpectrumWavelengthNm && nm[i] <= kMaxSpectrumWavelengthNm))
      return fmt::format("wavelength {} nm is outside [{}, {}] nm", nm[i], kMinSpectrumWavelengthNm,
                         kMaxSpectrumWavelengthNm);
    if (i > 0 && !(nm[i] > nm[i - 1]))
      return fmt::format("wavelengths must increase: {} nm follows {} nm", nm[i], nm[i - 1]);
    if (!(values[i] >= 0.0) || std::isinf(values[i]))
      return fmt::format("{} value {} at {} nm", values[i] < 0.0 ? "negative" : "non-finite", values[i], nm[i]);
    if (values[i] > max_value)
      return fmt::format("reflectance {} at {} nm is above {} (a surface cannot reflect more than it receives)",
                         values[i], nm[i], max_value);
  }
  return {};
}

}  // namespace prism
