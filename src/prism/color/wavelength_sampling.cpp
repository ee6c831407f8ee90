// Slot techniques of the wavelength sampling strategies (see wavelength_sampling.h).
#include "prism/color/wavelength_sampling.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "prism/core/branch_free.h"
#include "prism/core/error.h"
#include "prism/core/float_lanes.h"
#include "prism/core/log4.h"
#include "prism/sampling/piecewise_constant.h"

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
  double nm_per_ln_ratio;       // 1/(2A): λ − B = ln((1 + t)/(1 − t)) / (2A)
  double pdf_per_one_minus_t2;  // A / (tanh(A(780 − B)) − tanh(A(380 − B)))

  explicit PreparedLobe(const CoshLobe& l)
      : a_per_nm(l.a_per_nm), center_nm(l.center_nm), tanh_low(l.tanh_low()),
        tanh_range(l.tanh_high() - l.tanh_low()), nm_per_ln_ratio(0.5 / a_per_nm),
        pdf_per_one_minus_t2(a_per_nm / tanh_range) {}

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

// The cosh3 lobes, tabulated (see wavelength_sampling.h): each lobe's exact mass in every
// 1 nm cell of [380, 780] nm (its CDF is closed-form), sampled and evaluated as the
// piecewise-constant density with those masses, i.e. the lobe averaged over each
// nanometre: within e^a − 1 (0.8 %) of the cosh anywhere in the cell, as |d ln p/dλ| ≤ 2a
// and a point is at most ½ nm from wherever the lobe equals its average. The analytic
// inverse (atanh) plus three cosh per wavelength for the MIS pdf cost ≈ 265 ns per
// 4-wavelength sample; a piecewise-linear table with exact quadratic inversion 73 ns; this
// table 38 ns: a guide-table lookup, one division and one load of the effective pdf per
// wavelength (docs/performance-design.md "Wavelength sampling cost").
constexpr int kLobeCells = 400;  // 1 nm each

struct TabulatedLobe {
  PiecewiseConstant1D density;
  double center_shift;  // cdf(B) − ½ of the tabulated lobe: u = ½ lands on the centre B

  explicit TabulatedLobe(const CoshLobe& lobe)
      : density(tabulate(lobe), static_cast<float>(kVisibleMinNm), static_cast<float>(kVisibleMaxNm)),
        center_shift(0.0) {
    density.build_guide_table();
    // The table's own CDF at the centre, so that u = ½ inverts to B exactly.
    const double position = lobe.center_nm - kVisibleMinNm;
    const int cell = static_cast<int>(position);
    center_shift = double(density.cdf(cell)) + (position - cell) * double(density.pmf(cell)) - 0.5;
  }
  static std::vector<float> tabulate(const CoshLobe& lobe) {
    std::vector<float> mass;
    for (int i = 0; i < kLobeCells; ++i)
      mass.push_back(static_cast<float>(lobe.cdf(kVisibleMinNm + i + 1) - lobe.cdf(kVisibleMinNm + i)));
    return mass;
  }
};

struct ThreeCoshTables {
  // What a tuple of `count` wavelengths does per slot, worked out once per count: which
  // lobe, which way it runs through u, and its shift (see three_cosh_slot_u below).
  struct SlotPlan {
    const PiecewiseConstant1D* density;
    bool reversed;
    double center_shift, rotation;  // added to u in that order
  };
  static constexpr int kMaxTupleWavelengths = 8;  // the renderer's largest N
  struct TuplePlan {
    std::array<SlotPlan, kMaxTupleWavelengths> slots;
    std::vector<float> effective_pdf;  // per 1 nm cell: Σ_l w_l p_l, the pdf every λ_i carries
  };
  TabulatedLobe lobes[3] = {TabulatedLobe(kThreeCoshLobes[0]), TabulatedLobe(kThreeCoshLobes[1]),
                            TabulatedLobe(kThreeCoshLobes[2])};
  std::array<TuplePlan, kMaxTupleWavelengths + 1> plans{};  // by count

  ThreeCoshTables() {
    for (int count = 1; count <= kMaxTupleWavelengths; ++count) {
      TuplePlan& plan = plans[static_cast<std::size_t>(count)];
      const std::array<double, 3> weights = lobe_weights(count);
      for (int slot = 0; slot < count; ++slot) plan.slots[static_cast<std::size_t>(slot)] = slot_plan(slot, count);
      for (int cell = 0; cell < kLobeCells; ++cell) plan.effective_pdf.push_back(effective_pdf(weights, cell));
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
  // Σ_l w_l p_l in one 1 nm cell (the lobes share their cells), rounded to float once.
  float effective_pdf(const std::array<double, 3>& weights, int cell) const {
    double sum = 0.0;
    for (int l = 0; l < 3; ++l)
      sum += weights[static_cast<std::size_t>(l)] * double(lobes[l].density.pmf(cell)) /
             (kVisibleRangeNm / kLobeCells);
    return static_cast<float>(sum);
  }
  // The cell a wavelength falls in (the last one for 780 nm); −1 outside [380, 780] nm.
  int cell_of(double nm) const {
    if (!(nm >= kVisibleMinNm && nm <= kVisibleMaxNm)) return -1;
    return lobes[0].density.cell(static_cast<float>(nm));
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
    case WavelengthStrategy::cosh3: return three_cosh_lobe(slot).density.pdf(static_cast<float>(wavelength_nm));
  }
  return 0.0;
}

double sample_wavelength_slot(WavelengthStrategy strategy, int slot, double u) {
  switch (strategy) {
    case WavelengthStrategy::hero: return kVisibleMinNm + u * kVisibleRangeNm;
    case WavelengthStrategy::cosh: return radziszewski_lobe().sample(u);
    case WavelengthStrategy::cosh3:
      return three_cosh_lobe(slot).density.sample_continuous(static_cast<float>(u)).x;
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
  // std::floor, a libm call in a build without SSE4.1, and without a branch on which way
  // (a coin flip per slot; core/branch_free.h).
  double shifted = along + slot.center_shift + slot.rotation;
  shifted -= select_less(shifted, 1.0, 0.0, 1.0);  // 1 where shifted ≥ 1
  shifted += select_less(shifted, 0.0, 1.0, 0.0);  // 1 where shifted < 0
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
  const ThreeCoshTables& tables = three_cosh_tables();
  const int cell = tables.cell_of(wavelength_nm);
  if (cell < 0) return 0.0;
  if (count >= 1 && count <= ThreeCoshTables::kMaxTupleWavelengths)
    return tables.plans[static_cast<std::size_t>(count)].effective_pdf[static_cast<std::size_t>(cell)];
  return tables.effective_pdf(ThreeCoshTables::lobe_weights(count), cell);
}

void sample_three_cosh_wavelengths(double u, int count, float* wavelength_nm, float* pdf) {
  // The same slot_u / sample_wavelength_slot / wavelength_pdf as the generic path, with
  // every per-slot constant (lobe, direction, shift) and the effective pdf looked up from
  // the count's plan instead of recomputed with integer and floating-point divisions.
  const ThreeCoshTables& tables = three_cosh_tables();
  if (count < 1 || count > ThreeCoshTables::kMaxTupleWavelengths)
    throw std::invalid_argument("sample_three_cosh_wavelengths: " + std::to_string(count) +
                                " wavelengths per tuple (1 to 8 are planned)");
  const ThreeCoshTables::TuplePlan& plan = tables.plans[static_cast<std::size_t>(count)];
  const PiecewiseConstant1D& cells = tables.lobes[0].density;  // every lobe has the same cells
  for (int i = 0; i < count; ++i) {
    const ThreeCoshTables::SlotPlan& slot = plan.slots[static_cast<std::size_t>(i)];
    const float nm = slot.density->sample_continuous(static_cast<float>(three_cosh_slot_u(slot, u))).x;
    wavelength_nm[i] = nm;
    pdf[i] = plan.effective_pdf[static_cast<std::size_t>(cells.cell(nm))];
  }
}

namespace {

// Slots first … first + 3 of a cosh tuple (sample_cosh_wavelengths), n ≤ 4 of them stored.
// Each slot's number, tanh, ratio, pdf and λ are the scalar code's operations in the same
// order, two slots per SSE2 double instruction; the four logarithms are one log4.
void cosh_tuple_slots(const PreparedLobe& lobe, double u, double slot_step, int first, int n, float* wavelength_nm,
                      float* pdf) {
#if defined(__SSE2__)
  const __m128d one = _mm_set1_pd(1.0);
  __m128d ratio[2], density[2];
  for (int half = 0; half < 2; ++half) {
    const int i = first + 2 * half;
    // frac(u + i/count): u ∈ [0, 1), so one wrap at most.
    __m128d along = _mm_add_pd(_mm_set1_pd(u), _mm_mul_pd(_mm_set_pd(i + 1, i), _mm_set1_pd(slot_step)));
    along = _mm_sub_pd(along, _mm_and_pd(_mm_cmpge_pd(along, one), one));
    const __m128d t = _mm_add_pd(_mm_set1_pd(lobe.tanh_low), _mm_mul_pd(along, _mm_set1_pd(lobe.tanh_range)));
    ratio[half] = _mm_div_pd(_mm_add_pd(one, t), _mm_sub_pd(one, t));
    density[half] = _mm_mul_pd(_mm_set1_pd(lobe.pdf_per_one_minus_t2), _mm_sub_pd(one, _mm_mul_pd(t, t)));
  }
  const __m128 ln = log4_ps(_mm_movelh_ps(_mm_cvtpd_ps(ratio[0]), _mm_cvtpd_ps(ratio[1])));
  __m128d nm[2];
  const __m128d low = _mm_set1_pd(kVisibleMinNm), high = _mm_set1_pd(kVisibleMaxNm);
  for (int half = 0; half < 2; ++half) {
    const __m128d ln_pd = _mm_cvtps_pd(half == 0 ? ln : _mm_movehl_ps(ln, ln));
    nm[half] = _mm_add_pd(_mm_set1_pd(lobe.center_nm), _mm_mul_pd(ln_pd, _mm_set1_pd(lobe.nm_per_ln_ratio)));
    nm[half] = _mm_min_pd(_mm_max_pd(nm[half], low), high);
  }
  const __m128 nm_ps = _mm_movelh_ps(_mm_cvtpd_ps(nm[0]), _mm_cvtpd_ps(nm[1]));
  const __m128 pdf_ps = _mm_movelh_ps(_mm_cvtpd_ps(density[0]), _mm_cvtpd_ps(density[1]));
  if (n == 4) {
    // A whole tuple of four (the default): two stores, not the loop below, whose
    // variable count GCC leaves as a loop of scalar copies (Callgrind: a quarter of the
    // call's instructions, docs/performance-design.md "Instruction cuts").
    _mm_storeu_ps(wavelength_nm + first, nm_ps);
    _mm_storeu_ps(pdf + first, pdf_ps);
    return;
  }
  alignas(16) std::array<float, 4> nm_out, pdf_out;
  _mm_store_ps(nm_out.data(), nm_ps);
  _mm_store_ps(pdf_out.data(), pdf_ps);
#else
  std::array<float, 4> ratio{1.0f, 1.0f, 1.0f, 1.0f}, pdf_out{};
  for (int k = 0; k < 4; ++k) {
    double along = u + (first + k) * slot_step;
    along -= select_less(along, 1.0, 0.0, 1.0);  // core/branch_free.h
    const double t = lobe.tanh_low + along * lobe.tanh_range;
    ratio[static_cast<std::size_t>(k)] = static_cast<float>((1.0 + t) / (1.0 - t));
    pdf_out[static_cast<std::size_t>(k)] = static_cast<float>(lobe.pdf_per_one_minus_t2 * (1.0 - t * t));
  }
  const std::array<float, 4> ln = log4(ratio);
  std::array<float, 4> nm_out;
  for (std::size_t k = 0; k < 4; ++k)
    nm_out[k] = static_cast<float>(
        std::clamp(lobe.center_nm + double(ln[k]) * lobe.nm_per_ln_ratio, kVisibleMinNm, kVisibleMaxNm));
#endif
  for (int k = 0; k < n; ++k) {
    wavelength_nm[first + k] = nm_out[static_cast<std::size_t>(k)];
    pdf[first + k] = pdf_out[static_cast<std::size_t>(k)];
  }
}

}  // namespace

namespace {

// Four slots (fewer at a tuple's end) of a cosh tuple, for cosh_tuple_slots.
struct CoshQuad {
  double u;
  int first, n;
  float* wavelength_nm;
  float* pdf;
};

#if PRISM_FLOAT_LANES_AVX2
PRISM_TARGET_REGION_BEGIN("avx2")

// cosh_tuple_slots of two quads at once: each quad's four slots in a register of four
// doubles instead of two of two, the eight ratios' logarithms in one log8. The same
// operations on the same operands in every slot, so the same bits.
void cosh_quad_pair_avx2(const PreparedLobe& lobe, double slot_step, const CoshQuad& a, const CoshQuad& b) {
  const __m256d one = _mm256_set1_pd(1.0);
  const CoshQuad* quad[2] = {&a, &b};
  __m256d ratio[2], density[2];
  for (int h = 0; h < 2; ++h) {
    const int i = quad[h]->first;
    __m256d along = _mm256_add_pd(_mm256_set1_pd(quad[h]->u),
                                  _mm256_mul_pd(_mm256_setr_pd(i, i + 1, i + 2, i + 3), _mm256_set1_pd(slot_step)));
    along = _mm256_sub_pd(along, _mm256_and_pd(_mm256_cmp_pd(along, one, _CMP_GE_OS), one));
    const __m256d t = _mm256_add_pd(_mm256_set1_pd(lobe.tanh_low), _mm256_mul_pd(along, _mm256_set1_pd(lobe.tanh_range)));
    ratio[h] = _mm256_div_pd(_mm256_add_pd(one, t), _mm256_sub_pd(one, t));
    density[h] = _mm256_mul_pd(_mm256_set1_pd(lobe.pdf_per_one_minus_t2), _mm256_sub_pd(one, _mm256_mul_pd(t, t)));
  }
  const __m256 ln = log8_ps(_mm256_set_m128(_mm256_cvtpd_ps(ratio[1]), _mm256_cvtpd_ps(ratio[0])));
  const __m256d low = _mm256_set1_pd(kVisibleMinNm), high = _mm256_set1_pd(kVisibleMaxNm);
  for (int h = 0; h < 2; ++h) {
    const __m256d ln_pd = _mm256_cvtps_pd(h == 0 ? _mm256_castps256_ps128(ln) : _mm256_extractf128_ps(ln, 1));
    __m256d nm = _mm256_add_pd(_mm256_set1_pd(lobe.center_nm), _mm256_mul_pd(ln_pd, _mm256_set1_pd(lobe.nm_per_ln_ratio)));
    nm = _mm256_min_pd(_mm256_max_pd(nm, low), high);
    const CoshQuad& q = *quad[h];
    if (q.n == 4) {
      _mm_storeu_ps(q.wavelength_nm + q.first, _mm256_cvtpd_ps(nm));
      _mm_storeu_ps(q.pdf + q.first, _mm256_cvtpd_ps(density[h]));
      continue;
    }
    alignas(16) std::array<float, 4> nm_out, pdf_out;
    _mm_store_ps(nm_out.data(), _mm256_cvtpd_ps(nm));
    _mm_store_ps(pdf_out.data(), _mm256_cvtpd_ps(density[h]));
    for (int k = 0; k < q.n; ++k) {
      q.wavelength_nm[q.first + k] = nm_out[static_cast<std::size_t>(k)];
      q.pdf[q.first + k] = pdf_out[static_cast<std::size_t>(k)];
    }
  }
}

PRISM_TARGET_REGION_END
#endif

const bool kCoshAvx2 = lanes::avx2_supported();

// The quads' slots: two at a time in AVX2 where `width` and the processor allow, else one
// at a time in SSE2 (the same bits either way).
void cosh_quads(const PreparedLobe& lobe, double slot_step, const CoshQuad* quads, int count, CoshVectorWidth width) {
  int k = 0;
#if PRISM_FLOAT_LANES_AVX2
  if (width == CoshVectorWidth::widest && kCoshAvx2)
    for (; k + 1 < count; k += 2) cosh_quad_pair_avx2(lobe, slot_step, quads[k], quads[k + 1]);
#else
  (void)width;
#endif
  for (; k < count; ++k)
    cosh_tuple_slots(lobe, quads[k].u, slot_step, quads[k].first, quads[k].n, quads[k].wavelength_nm, quads[k].pdf);
}

}  // namespace

void sample_cosh_wavelengths(double u, int count, float* wavelength_nm, float* pdf, CoshVectorWidth width) {
  // The generic loop's slot_u and inverse CDF, with the pdf taken from the tanh the
  // inversion starts from instead of a cosh of the result: λ = B + atanh(t)/A with
  // t = tanh(A(λ − B)), and 1/cosh²(x) = 1 − tanh²(x), so p(λ) = A (1 − t²) / (tanh(A(780 − B))
  // − tanh(A(380 − B))): the same density, for one float logarithm per wavelength instead of
  // a double atanh and a double cosh (BM_SampleWavelengths: cosh 216–245 → 66–79 ns).
  // atanh(t) = ½ ln((1 + t)/(1 − t)), the logarithm in float: |t| ≤ 0.94 here, so the ratio
  // stays in [0.1, 33], and log4's error there (< 1e-6) moves λ by < 1e-4 nm. Four slots at
  // a time, eight in AVX2 (docs/performance-design.md "Wavelength sampling cost").
  sample_cosh_wavelengths({&u, 1}, count, {&wavelength_nm, 1}, {&pdf, 1}, width);
}

void sample_cosh_wavelengths(std::span<const double> u, int count, std::span<float* const> wavelength_nm,
                             std::span<float* const> pdf, CoshVectorWidth width) {
  const PreparedLobe& lobe = radziszewski_lobe();
  const double slot_step = 1.0 / count;  // exact for 1, 2, 4 and 8 wavelengths
  std::array<CoshQuad, 4> quads;
  int queued = 0;
  for (std::size_t tuple = 0; tuple < u.size(); ++tuple)
    for (int first = 0; first < count; first += 4) {
      quads[static_cast<std::size_t>(queued++)] = {u[tuple], first, std::min(4, count - first), wavelength_nm[tuple],
                                                   pdf[tuple]};
      if (queued == static_cast<int>(quads.size())) {
        cosh_quads(lobe, slot_step, quads.data(), queued, width);
        queued = 0;
      }
    }
  cosh_quads(lobe, slot_step, quads.data(), queued, width);
}

}  // namespace prism::color
