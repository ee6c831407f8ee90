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

namespace {

// The lobes' constants, computed once: tanh at both ends of [380, 780] nm (the CDF is
// linear in tanh) and the cosh3 shift that lands u = ½ on each lobe's centre. Recomputing
// them per call made wavelength sampling the renderer's hottest function.
struct PreparedLobe {
  double a_per_nm, center_nm, tanh_low, tanh_range, center_shift;

  explicit PreparedLobe(const CoshLobe& l)
      : a_per_nm(l.a_per_nm), center_nm(l.center_nm), tanh_low(l.tanh_low()),
        tanh_range(l.tanh_high() - l.tanh_low()), center_shift(l.cdf(l.center_nm) - 0.5) {}

  double pdf(double nm) const {
    if (nm < kVisibleMinNm || nm > kVisibleMaxNm) return 0.0;
    const double c = std::cosh(a_per_nm * (nm - center_nm));
    return a_per_nm / (c * c * tanh_range);
  }
  double sample(double u) const {
    const double nm = center_nm + std::atanh(tanh_low + u * tanh_range) / a_per_nm;
    return std::clamp(nm, kVisibleMinNm, kVisibleMaxNm);
  }
};

const PreparedLobe& radziszewski_lobe() {
  static const PreparedLobe lobe(kRadziszewskiLobe);
  return lobe;
}

const PreparedLobe& three_cosh_lobe(int slot) {
  static const PreparedLobe lobes[3] = {PreparedLobe(kThreeCoshLobes[0]), PreparedLobe(kThreeCoshLobes[1]),
                                        PreparedLobe(kThreeCoshLobes[2])};
  return lobes[slot % 3];
}

}  // namespace

double wavelength_slot_pdf(WavelengthStrategy strategy, int slot, double wavelength_nm) {
  switch (strategy) {
    case WavelengthStrategy::hero:
      return (wavelength_nm >= kVisibleMinNm && wavelength_nm <= kVisibleMaxNm) ? 1.0 / kVisibleRangeNm
                                                                                : 0.0;
    case WavelengthStrategy::cosh: return radziszewski_lobe().pdf(wavelength_nm);
    case WavelengthStrategy::cosh3: return three_cosh_lobe(slot).pdf(wavelength_nm);
  }
  return 0.0;
}

double sample_wavelength_slot(WavelengthStrategy strategy, int slot, double u) {
  switch (strategy) {
    case WavelengthStrategy::hero: return kVisibleMinNm + u * kVisibleRangeNm;
    case WavelengthStrategy::cosh: return radziszewski_lobe().sample(u);
    case WavelengthStrategy::cosh3: return three_cosh_lobe(slot).sample(u);
  }
  return kVisibleMinNm;
}

double slot_u(WavelengthStrategy strategy, double u, int slot, int count) {
  double shifted = u + double(slot) / count;
  if (strategy == WavelengthStrategy::cosh3) {
    const int lobe = slot % 3, copy = slot / 3, copies = (count - lobe + 2) / 3;
    shifted = u + three_cosh_lobe(lobe).center_shift + double(copy) / copies;
  }
  return shifted - std::floor(shifted);
}

double wavelength_pdf(WavelengthStrategy strategy, int count, double wavelength_nm) {
  if (strategy != WavelengthStrategy::cosh3) return wavelength_slot_pdf(strategy, 0, wavelength_nm);
  // Slot i uses lobe i mod 3: lobe l serves (count − l + 2) / 3 of the slots.
  double sum = 0.0;
  for (int lobe = 0; lobe < std::min(count, 3); ++lobe)
    sum += ((count - lobe + 2) / 3) * three_cosh_lobe(lobe).pdf(wavelength_nm);
  return sum / count;
}

}  // namespace prism::color
