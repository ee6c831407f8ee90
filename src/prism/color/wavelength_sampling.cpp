// Slot techniques of the wavelength sampling strategies (see wavelength_sampling.h).
#include "prism/color/wavelength_sampling.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "prism/color/piecewise_linear_density.h"
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

// The cosh lobe's constants, computed once: tanh at both ends of [380, 780] nm (the CDF is
// linear in tanh). Recomputing them per call made wavelength sampling the renderer's
// hottest function.
struct PreparedLobe {
  double a_per_nm, center_nm, tanh_low, tanh_range;

  explicit PreparedLobe(const CoshLobe& l)
      : a_per_nm(l.a_per_nm), center_nm(l.center_nm), tanh_low(l.tanh_low()),
        tanh_range(l.tanh_high() - l.tanh_low()) {}

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

// The cosh3 lobes, tabulated (see wavelength_sampling.h): each lobe's density at 1 nm
// nodes, linear in between, sampled by exact inversion of that piecewise-linear density.
// The analytic inverse (atanh) plus three cosh per wavelength for the MIS pdf cost ≈ 265 ns
// per 4-wavelength sample; the table needs a guide-table lookup, one sqrt and three
// linear interpolations at a shared node index. The 1 nm spacing keeps the table within
// 3e-5 (relative) of the cosh lobe (interpolation error h²·max|p''|/8 with p''/p ≤ 2a²),
// and puts the kinks on whole nanometres.
constexpr double kLobeTableStepNm = 1.0;

struct TabulatedLobe {
  PiecewiseLinearDensity density;
  double center_shift;  // cdf(B) − ½ of the tabulated lobe: u = ½ lands on the centre B

  explicit TabulatedLobe(const CoshLobe& lobe) : density(tabulate(lobe)), center_shift(0.0) {
    // CDF of the table at the centre: integrate the piecewise-linear density up to B.
    double cdf = 0.0;
    for (double nm = kVisibleMinNm; nm < lobe.center_nm; nm += kLobeTableStepNm) {
      const double next = std::min(nm + kLobeTableStepNm, lobe.center_nm);
      cdf += 0.5 * (next - nm) * (density.pdf(nm) + density.pdf(next));
    }
    center_shift = cdf - 0.5;
  }
  static PiecewiseLinearDensity tabulate(const CoshLobe& lobe) {
    const int nodes = static_cast<int>(kVisibleRangeNm / kLobeTableStepNm + 0.5) + 1;
    std::vector<double> values;
    for (int n = 0; n < nodes; ++n) values.push_back(lobe.pdf(kVisibleMinNm + n * kLobeTableStepNm));
    return PiecewiseLinearDensity(kVisibleMinNm, kLobeTableStepNm, std::move(values));
  }
};

struct ThreeCoshTables {
  // What a tuple of `count` wavelengths does per slot, worked out once per count: which
  // lobe, which way it runs through u, and its shift (see three_cosh_slot_u below).
  struct SlotPlan {
    const PiecewiseLinearDensity* density;
    bool reversed;
    double center_shift, rotation;  // added to u in that order, so the sum rounds as it always did
  };
  static constexpr int kMaxTupleWavelengths = 8;  // the renderer's largest N
  struct TuplePlan {
    std::array<double, 3> weights;
    std::array<SlotPlan, kMaxTupleWavelengths> slots;
  };
  TabulatedLobe lobes[3] = {TabulatedLobe(kThreeCoshLobes[0]), TabulatedLobe(kThreeCoshLobes[1]),
                            TabulatedLobe(kThreeCoshLobes[2])};
  // The three lobes' node values side by side: the effective pdf of a wavelength needs all
  // three at the same node, so one index computation and one cache line serve them.
  std::vector<std::array<double, 3>> node_pdfs;
  std::array<TuplePlan, kMaxTupleWavelengths + 1> plans{};  // by count

  ThreeCoshTables() {
    for (double nm = kVisibleMinNm; nm <= kVisibleMaxNm; nm += kLobeTableStepNm)
      node_pdfs.push_back({lobes[0].density.pdf(nm), lobes[1].density.pdf(nm), lobes[2].density.pdf(nm)});
    for (int count = 1; count <= kMaxTupleWavelengths; ++count) {
      TuplePlan& plan = plans[static_cast<std::size_t>(count)];
      plan.weights = lobe_weights(count);
      for (int slot = 0; slot < count; ++slot) plan.slots[static_cast<std::size_t>(slot)] = slot_plan(slot, count);
    }
  }
  SlotPlan slot_plan(int slot, int count) const {
    const int lobe = slot % 3, copy = slot / 3, copies = (count - lobe + 2) / 3;
    return {&lobes[lobe].density, lobe == 0, lobes[lobe].center_shift, double(copy) / copies};
  }
  // Weight of each lobe's pdf in (1/count) Σ_slots p_slot: slot i uses lobe i mod 3, so
  // lobe l serves (count − l + 2)/3 of the slots.
  static std::array<double, 3> lobe_weights(int count) {
    std::array<double, 3> w{};
    for (int lobe = 0; lobe < std::min(count, 3); ++lobe)
      w[static_cast<std::size_t>(lobe)] = double((count - lobe + 2) / 3) / count;
    return w;
  }
  // Σ_l w_l p_l(λ): the same piecewise-linear pdfs, interpolated once.
  double effective_pdf(const std::array<double, 3>& weights, double nm) const {
    const double position = (nm - kVisibleMinNm) * (1.0 / kLobeTableStepNm);
    const double last_segment = double(node_pdfs.size() - 2);
    if (!(position >= 0.0) || position > last_segment + 1.0) return 0.0;
    const std::size_t n = static_cast<std::size_t>(std::min(position, last_segment));
    const double t = position - double(n);
    const std::array<double, 3>& a = node_pdfs[n];
    const std::array<double, 3>& b = node_pdfs[n + 1];
    return weights[0] * (a[0] + t * (b[0] - a[0])) + weights[1] * (a[1] + t * (b[1] - a[1])) +
           weights[2] * (a[2] + t * (b[2] - a[2]));
  }
};

const ThreeCoshTables& three_cosh_tables() {
  static const ThreeCoshTables tables;
  return tables;
}
const TabulatedLobe& three_cosh_lobe(int slot) { return three_cosh_tables().lobes[slot % 3]; }

}  // namespace

double wavelength_slot_pdf(WavelengthStrategy strategy, int slot, double wavelength_nm) {
  switch (strategy) {
    case WavelengthStrategy::hero:
      return (wavelength_nm >= kVisibleMinNm && wavelength_nm <= kVisibleMaxNm) ? 1.0 / kVisibleRangeNm
                                                                                : 0.0;
    case WavelengthStrategy::cosh: return radziszewski_lobe().pdf(wavelength_nm);
    case WavelengthStrategy::cosh3: return three_cosh_lobe(slot).density.pdf(wavelength_nm);
  }
  return 0.0;
}

double sample_wavelength_slot(WavelengthStrategy strategy, int slot, double u) {
  switch (strategy) {
    case WavelengthStrategy::hero: return kVisibleMinNm + u * kVisibleRangeNm;
    case WavelengthStrategy::cosh: return radziszewski_lobe().sample(u);
    case WavelengthStrategy::cosh3: return three_cosh_lobe(slot).density.sample(u);
  }
  return kVisibleMinNm;
}

namespace {

// The number cosh3's slot inverts (see wavelength_sampling.h): lobe 0 runs through u
// backwards; each lobe is shifted so that u = ½ lands on its centre, and repeated lobes
// rotate evenly among themselves.
double three_cosh_slot_u(const ThreeCoshTables::SlotPlan& slot, double u) {
  const double along = slot.reversed ? 1.0 - u : u;
  // ∈ (−1, 2): along ∈ [0, 1], |center_shift| < ½, rotation < 1. Wrapped without
  // std::floor, a libm call in a build without SSE4.1.
  double shifted = along + slot.center_shift + slot.rotation;
  shifted -= double(shifted >= 1.0);
  shifted += double(shifted < 0.0);
  return shifted;
}

}  // namespace

double slot_u(WavelengthStrategy strategy, double u, int slot, int count) {
  if (strategy == WavelengthStrategy::cosh3) return three_cosh_slot_u(three_cosh_tables().slot_plan(slot, count), u);
  const double shifted = u + double(slot) / count;
  return shifted - std::floor(shifted);
}

double wavelength_pdf(WavelengthStrategy strategy, int count, double wavelength_nm) {
  if (strategy != WavelengthStrategy::cosh3) return wavelength_slot_pdf(strategy, 0, wavelength_nm);
  // Slot i uses lobe i mod 3.
  return three_cosh_tables().effective_pdf(ThreeCoshTables::lobe_weights(count), wavelength_nm);
}

void sample_three_cosh_wavelengths(double u, int count, float* wavelength_nm, float* pdf) {
  // The same slot_u / sample_wavelength_slot / wavelength_pdf as the generic path, with
  // every per-slot constant (lobe, direction, shift, MIS weights) looked up from the
  // count's plan instead of recomputed with integer and floating-point divisions.
  const ThreeCoshTables& tables = three_cosh_tables();
  if (count < 1 || count > ThreeCoshTables::kMaxTupleWavelengths)
    throw std::invalid_argument("sample_three_cosh_wavelengths: " + std::to_string(count) +
                                " wavelengths per tuple (1 to 8 are planned)");
  const ThreeCoshTables::TuplePlan& plan = tables.plans[static_cast<std::size_t>(count)];
  for (int i = 0; i < count; ++i) {
    const ThreeCoshTables::SlotPlan& slot = plan.slots[static_cast<std::size_t>(i)];
    const double nm = slot.density->sample(three_cosh_slot_u(slot, u));
    wavelength_nm[i] = static_cast<float>(nm);
    pdf[i] = static_cast<float>(tables.effective_pdf(plan.weights, nm));
  }
}

}  // namespace prism::color
