#pragma once
// Strategies for drawing the N wavelengths a path carries, each unbiased for the
// estimator (1/N) Σ f(λ_i)/pdf_i of sampled_spectrum.h over [380, 780] nm.
//
// All three share one shape: slot i inverts its technique's CDF at u_i = frac(u + shift_i)
// (slot_u below). A shift modulo 1 keeps u_i uniform, so each λ_i's marginal density is
// its technique's pdf whatever the shifts; they only decide how the N wavelengths spread.
//   hero   Wilkie et al. 2014, "Hero Wavelength Spectral Sampling": uniform technique, so
//          λ_i = 380 + 400·frac(u + i/N) — one uniform hero plus N−1 evenly rotated partners.
//   cosh   Radziszewski et al. 2009: pdf ∝ 1/cosh²(A(λ−B)), A = 0.0072/nm, B = 538 nm, a
//          shape close to ȳ, normalised on [380, 780] with an analytic inverse CDF.
//   cosh3  three cosh lobes (A, B) = (0.0078, 600), (0.0072, 535), (0.0062, 445), one per
//          slot (slot i uses lobe i mod 3), each normalised on [380, 780] and tabulated:
//          the density used (sampled and returned) is piecewise constant on 1 nm cells,
//          each holding the lobe's exact mass (the lobe averaged over the nanometre, within
//          0.8 % of the cosh), inverted exactly (PiecewiseConstant1D with a guide table),
//          so pdf and samples agree to rounding. Lobe l's slots
//          share u shifted by cdf_l(B_l) − ½, so u = ½ lands every lobe on its centre B_l,
//          and repeated lobes (N > 3) are rotated evenly among themselves. Lobe 0 (600 nm)
//          runs through u backwards (1 − u; antithetic, Hammersley & Morton 1956): as u
//          grows, the 600 nm wavelength moves down while the other two move up, which
//          flattens the per-sample estimate as a function of u. It changes no marginal
//          density; measured on the Cornell box it lowers relMSE by 10 % (4 λ) and 6 %
//          (3 λ), 2 % at 8 λ, and by 1–20 % on a lit colour checker (BENCHMARKS.md,
//          "Wavelengths"); mirroring lobe 1 or 2 instead does worse. Combined as a
//          multi-sample MIS estimator with the balance heuristic (Veach 1997 §9.2): with
//          n_k samples from technique k, w_k = n_k p_k / Σ_j n_j p_j, and
//          Σ_k (1/n_k) Σ w_k f/p_k = (1/N) Σ_i f(λ_i) / p̄(λ_i), p̄ = (1/N) Σ_slots p_slot.
//          So each λ_i is stored with the effective pdf p̄, the average of the slot pdfs.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/cie_1931.h"
#include "prism/color/sampled_spectrum.h"

namespace prism::color {

// A density ∝ 1/cosh²(a (λ − b)) truncated to [380, 780] nm.
struct CoshLobe {
  double a_per_nm;
  double center_nm;

  // tanh(a(λ − b)) at the two ends: the CDF is linear in tanh, so it inverts in closed form.
  double tanh_low() const { return std::tanh(a_per_nm * (kVisibleMinNm - center_nm)); }
  double tanh_high() const { return std::tanh(a_per_nm * (kVisibleMaxNm - center_nm)); }

  double pdf(double wavelength_nm) const {
    if (wavelength_nm < kVisibleMinNm || wavelength_nm > kVisibleMaxNm) return 0.0;
    const double c = std::cosh(a_per_nm * (wavelength_nm - center_nm));
    return a_per_nm / (c * c * (tanh_high() - tanh_low()));
  }
  double cdf(double wavelength_nm) const {
    const double lo = tanh_low();
    const double t = std::tanh(a_per_nm * (std::clamp(wavelength_nm, kVisibleMinNm, kVisibleMaxNm) - center_nm));
    return (t - lo) / (tanh_high() - lo);
  }
  double sample(double u) const {
    const double lo = tanh_low();
    const double nm = center_nm + std::atanh(lo + u * (tanh_high() - lo)) / a_per_nm;
    return std::clamp(nm, kVisibleMinNm, kVisibleMaxNm);
  }
};

inline constexpr CoshLobe kRadziszewskiLobe{0.0072, 538.0};
inline constexpr std::array<CoshLobe, 3> kThreeCoshLobes{
    {{0.0078, 600.0}, {0.0072, 535.0}, {0.0062, 445.0}}};

enum class WavelengthStrategy { hero, cosh, cosh3 };

// "hero", "cosh", "cosh3". Unknown: UsageError.
WavelengthStrategy parse_wavelength_strategy(std::string_view name);
std::string_view wavelength_strategy_name(WavelengthStrategy strategy);
std::vector<std::string> wavelength_strategy_names();

// Density of slot `slot` of `count` under `strategy` (the technique it inverts).
double wavelength_slot_pdf(WavelengthStrategy strategy, int slot, double wavelength_nm);
// The slot's inverse CDF at u ∈ [0, 1).
double sample_wavelength_slot(WavelengthStrategy strategy, int slot, double u);
// The effective pdf stored with every λ_i: average of the slot pdfs over `count` slots.
double wavelength_pdf(WavelengthStrategy strategy, int count, double wavelength_nm);

// The number slot `slot` of `count` inverts, from the sample's primary number u:
// hero, cosh: frac(u + slot/count) (Wilkie et al.'s rotation); cosh3: see above.
double slot_u(WavelengthStrategy strategy, double u, int slot, int count);

// cosh3's sample_wavelengths in one call (the generic loop below costs three calls per
// wavelength): wavelength_nm[i], pdf[i] for i < count, the same values as that loop.
// count ∈ [1, 8] (std::invalid_argument otherwise): the per-count slot constants are
// tabulated for the renderer's tuple sizes.
void sample_three_cosh_wavelengths(double u, int count, float* wavelength_nm, float* pdf);

// cosh's tuple in one call: the generic loop's wavelengths with atanh as a float
// logarithm, each pdf from the tanh its inversion starts from (1/cosh² = 1 − tanh²)
// instead of a cosh of λ; within 1e-4 nm and float rounding of the loop's
// (wavelength_sampling_test), in a third of its time.
// In SSE2, four slots at a time, or in AVX2 where the processor has it, eight (two tuples
// of four, or one of eight): the same bits (wavelength_sampling_test). `sse2` keeps to SSE2,
// for that comparison.
enum class CoshVectorWidth { widest, sse2 };
void sample_cosh_wavelengths(double u, int count, float* wavelength_nm, float* pdf,
                             CoshVectorWidth width = CoshVectorWidth::widest);
// Several tuples in one call, tuple i from u[i] into wavelength_nm[i][0 … count) and
// pdf[i][0 … count): the same values as a call per tuple, tuples of four two at a time in
// AVX2.
void sample_cosh_wavelengths(std::span<const double> u, int count, std::span<float* const> wavelength_nm,
                             std::span<float* const> pdf, CoshVectorWidth width = CoshVectorWidth::widest);

template <int N>
SampledWavelengths<N> sample_wavelengths(WavelengthStrategy strategy, double u) {
  SampledWavelengths<N> w;
  if (strategy == WavelengthStrategy::cosh3) {
    sample_three_cosh_wavelengths(u, N, w.wavelength_nm.data(), w.pdf.data());
    return w;
  }
  if (strategy == WavelengthStrategy::cosh) {
    sample_cosh_wavelengths(u, N, w.wavelength_nm.data(), w.pdf.data());
    return w;
  }
  for (int i = 0; i < N; ++i) {
    const double nm = sample_wavelength_slot(strategy, i, slot_u(strategy, u, i, N));
    w.wavelength_nm[i] = static_cast<float>(nm);
    w.pdf[i] = static_cast<float>(wavelength_pdf(strategy, N, nm));
  }
  return w;
}

// sample_wavelengths of two samples: the same values, the cosh tuples in one call.
template <int N>
void sample_wavelength_pair(WavelengthStrategy strategy, const double (&u)[2], SampledWavelengths<N>& first,
                            SampledWavelengths<N>& second) {
  if (strategy != WavelengthStrategy::cosh) {
    first = sample_wavelengths<N>(strategy, u[0]);
    second = sample_wavelengths<N>(strategy, u[1]);
    return;
  }
  float* const nm[2] = {first.wavelength_nm.data(), second.wavelength_nm.data()};
  float* const pdf[2] = {first.pdf.data(), second.pdf.data()};
  sample_cosh_wavelengths(u, N, nm, pdf);
}

// Stratified first samples: the primary number of sample `sample_index` of a pixel is
// jittered inside one of nine equal strata of [0, 1), visited in kFirstSampleStrata order.
// The first stratum is the middle one, [4/9, 5/9): there every cosh3 slot lands within
// about ±15 nm of its lobe's centre (slot_u), so sample 0 of every pixel carries ≈ 600,
// 535 and 445 nm and the first pass is already coloured. Each run of nine consecutive samples covers every
// stratum once, so the estimator is unbiased over complete runs of nine (stratified
// sampling); for other counts the bias is at most one stratum's share and decays as 1/spp.
inline constexpr std::array<int, 9> kFirstSampleStrata{4, 0, 8, 2, 6, 1, 7, 3, 5};
inline double stratified_wavelength_u(std::uint64_t sample_index, double jitter) {
  const int stratum = kFirstSampleStrata[sample_index % kFirstSampleStrata.size()];
  return (stratum + jitter) / double(kFirstSampleStrata.size());
}

}  // namespace prism::color
