// Slot techniques of the wavelength sampling strategies (see wavelength_sampling.h).
#include "prism/color/wavelength_sampling.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "prism/core/error.h"

namespace prism::color {

WavelengthStrategy parse_wavelength_strategy(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (lower == "hero") return WavelengthStrategy::hero;
  if (lower == "cosh") return WavelengthStrategy::cosh;
  if (lower == "cosh3") return WavelengthStrategy::cosh3;
  throw UsageError("unknown wavelength strategy '" + std::string(name) +
                   "' (known: hero, cosh, cosh3)");
}

std::string_view wavelength_strategy_name(WavelengthStrategy strategy) {
  switch (strategy) {
    case WavelengthStrategy::hero: return "hero";
    case WavelengthStrategy::cosh: return "cosh";
    case WavelengthStrategy::cosh3: return "cosh3";
  }
  return "hero";
}

std::vector<std::string> wavelength_strategy_names() { return {"hero", "cosh", "cosh3"}; }

double wavelength_slot_pdf(WavelengthStrategy strategy, int slot, double wavelength_nm) {
  switch (strategy) {
    case WavelengthStrategy::hero:
      return (wavelength_nm >= kVisibleMinNm && wavelength_nm <= kVisibleMaxNm) ? 1.0 / kVisibleRangeNm
                                                                                : 0.0;
    case WavelengthStrategy::cosh: return kRadziszewskiLobe.pdf(wavelength_nm);
    case WavelengthStrategy::cosh3: return kThreeCoshLobes[static_cast<std::size_t>(slot % 3)].pdf(wavelength_nm);
  }
  return 0.0;
}

double sample_wavelength_slot(WavelengthStrategy strategy, int slot, double u) {
  switch (strategy) {
    case WavelengthStrategy::hero: return kVisibleMinNm + u * kVisibleRangeNm;
    case WavelengthStrategy::cosh: return kRadziszewskiLobe.sample(u);
    case WavelengthStrategy::cosh3: return kThreeCoshLobes[static_cast<std::size_t>(slot % 3)].sample(u);
  }
  return kVisibleMinNm;
}

double slot_u(WavelengthStrategy strategy, double u, int slot, int count) {
  double shifted = u + double(slot) / count;
  if (strategy == WavelengthStrategy::cosh3) {
    const int lobe = slot % 3, copy = slot / 3, copies = (count - lobe + 2) / 3;
    const CoshLobe& l = kThreeCoshLobes[static_cast<std::size_t>(lobe)];
    shifted = u + (l.cdf(l.center_nm) - 0.5) + double(copy) / copies;
  }
  return shifted - std::floor(shifted);
}

double wavelength_pdf(WavelengthStrategy strategy, int count, double wavelength_nm) {
  if (strategy != WavelengthStrategy::cosh3) return wavelength_slot_pdf(strategy, 0, wavelength_nm);
  double sum = 0.0;
  for (int i = 0; i < count; ++i) sum += wavelength_slot_pdf(strategy, i, wavelength_nm);
  return sum / count;
}

}  // namespace prism::color
