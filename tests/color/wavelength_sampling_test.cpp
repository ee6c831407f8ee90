// Wavelength sampling strategies: chi-square goodness of fit of the sampled wavelengths
// against the pdfs they report, and unbiasedness of the spectral XYZ estimator.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "prism/color/illuminants.h"
#include "prism/color/sampled_spectrum.h"
#include "prism/color/spectrum.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/core/pcg32.h"
#include "support/chi_square.h"

namespace prism::color {
namespace {

// Chi-square tests in this file: 3 strategies × 2 sample counts + stratified = 7; overall
// false-alarm probability 1 % (Šidák).
const double kAlpha = test::sidak_alpha(0.01, 7);
constexpr int kBins = 80;  // 5 nm bins

// cosh3 samples and evaluates a tabulated density: each lobe constant on every whole-nm
// cell (wavelength_sampling.h). The midpoint sum over whole-nm cells is then exact.
double whole_nm_cell_sum(const std::function<double(double)>& f, double from_nm, double to_nm) {
  double sum = 0.0;
  for (double nm = from_nm; nm < to_nm; nm += 1.0) sum += f(nm + 0.5);
  return sum;
}

// ∫ over [a, b] of a slot pdf: for cosh3 the exact cell sum (a, b whole nm); otherwise
// Simpson's rule on 50 panels: the pdfs are smooth (cosh lobe) or constant, so the
// quadrature error (~1e-12 relative) is far below the statistical resolution of the test.
double integrate_pdf(WavelengthStrategy s, int slot, double a, double b) {
  if (s == WavelengthStrategy::cosh3)
    return whole_nm_cell_sum([&](double nm) { return wavelength_slot_pdf(s, slot, nm); }, a, b);
  constexpr int panels = 50;
  const double h = (b - a) / panels;
  double sum = wavelength_slot_pdf(s, slot, a) + wavelength_slot_pdf(s, slot, b);
  for (int i = 1; i < panels; ++i) sum += (i % 2 ? 4.0 : 2.0) * wavelength_slot_pdf(s, slot, a + i * h);
  return sum * h / 3.0;
}

template <int N>
void expect_wavelengths_follow_pdf(WavelengthStrategy strategy, bool stratified) {
  constexpr long kTuples = 90000;  // a multiple of 9: whole stratification cycles
  std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
  Pcg32 rng(7, 11);
  for (long t = 0; t < kTuples; ++t) {
    const double u = stratified ? stratified_wavelength_u(static_cast<std::uint64_t>(t), rng.next_double())
                                : rng.next_double();
    const SampledWavelengths<N> w = sample_wavelengths<N>(strategy, u);
    for (int i = 0; i < N; ++i) {
      const double nm = w.wavelength_nm[i];
      ASSERT_GE(nm, kVisibleMinNm);
      ASSERT_LE(nm, kVisibleMaxNm);
      // The stored pdf is the strategy's effective pdf at the sampled wavelength.
      ASSERT_NEAR(w.pdf[i], wavelength_pdf(strategy, N, nm), 1e-6 * w.pdf[i]);
      const int bin = std::min(kBins - 1, static_cast<int>((nm - kVisibleMinNm) / kVisibleRangeNm * kBins));
      observed[static_cast<std::size_t>(bin)] += 1.0;
    }
  }
  for (int b = 0; b < kBins; ++b) {
    const double lo = kVisibleMinNm + kVisibleRangeNm * b / kBins, hi = lo + kVisibleRangeNm / kBins;
    for (int i = 0; i < N; ++i) expected[static_cast<std::size_t>(b)] += kTuples * integrate_pdf(strategy, i, lo, hi);
  }
  const test::ChiSquareResult r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, kAlpha) << wavelength_strategy_name(strategy) << " N=" << N << ": " << r.message;
}

TEST(WavelengthSampling, HeroChiSquare) {
  expect_wavelengths_follow_pdf<4>(WavelengthStrategy::hero, false);
  expect_wavelengths_follow_pdf<3>(WavelengthStrategy::hero, false);
}
TEST(WavelengthSampling, CoshChiSquare) {
  expect_wavelengths_follow_pdf<4>(WavelengthStrategy::cosh, false);
  expect_wavelengths_follow_pdf<8>(WavelengthStrategy::cosh, false);
}
TEST(WavelengthSampling, ThreeLobeCoshChiSquare) {
  expect_wavelengths_follow_pdf<3>(WavelengthStrategy::cosh3, false);
  expect_wavelengths_follow_pdf<4>(WavelengthStrategy::cosh3, false);
}
TEST(WavelengthSampling, StratifiedFirstSamplesChiSquareOverWholeCycles) {
  expect_wavelengths_follow_pdf<3>(WavelengthStrategy::cosh3, true);
}

TEST(WavelengthSampling, PdfsAreNormalisedOnTheVisibleRange) {
  for (WavelengthStrategy s : {WavelengthStrategy::hero, WavelengthStrategy::cosh, WavelengthStrategy::cosh3})
    for (int slot = 0; slot < 3; ++slot) {
      double total = 0.0;  // Simpson per 5 nm bin, relative error ~1e-12
      for (int b = 0; b < kBins; ++b)
        total += integrate_pdf(s, slot, kVisibleMinNm + 5.0 * b, kVisibleMinNm + 5.0 * (b + 1));
      EXPECT_NEAR(total, 1.0, 1e-9);
    }
  // Analytic inverse CDF: cdf(sample(u)) = u.
  for (double u : {0.0, 0.1, 0.5, 0.93})
    EXPECT_NEAR(kRadziszewskiLobe.cdf(kRadziszewskiLobe.sample(u)), u, 1e-12);
}

TEST(WavelengthSampling, ThreeLobeTableIsInvertedExactlyAndStaysCloseToTheCoshLobes) {
  for (int slot = 0; slot < 3; ++slot) {
    auto pdf = [slot](double nm) { return wavelength_slot_pdf(WavelengthStrategy::cosh3, slot, nm); };
    // Exact inversion: the table's CDF at the sampled wavelength is u, up to rounding: u and
    // the CDF are floats (6e-8), and λ is a float near 600 nm (step 6e-5 nm) times a density
    // ≤ 0.005/nm (3e-7). Bound 1e-6.
    for (double u : {0.0, 1e-7, 0.013, 0.25, 0.5, 0.77, 0.999, 1.0 - 1e-12}) {
      const double nm = sample_wavelength_slot(WavelengthStrategy::cosh3, slot, u);
      const double whole = std::floor(nm);
      const double cdf = whole_nm_cell_sum(pdf, kVisibleMinNm, whole) + (nm - whole) * pdf(whole + 0.5);
      EXPECT_NEAR(cdf, u, 1e-6) << "slot " << slot << " u " << u;
    }
    // Each cell holds the lobe's exact mass (float rounding, 1e-7 of the total), so the
    // table is the lobe averaged over each nanometre; within a cell ln p varies by at most
    // 2a · ½ nm = a, so the average is within e^a − 1 (0.79 % for a = 0.0078/nm) of the
    // lobe at every point of the cell. The chi-square tests above compare against the
    // tabulated pdf itself, so this is what keeps the table honest.
    const CoshLobe& lobe = kThreeCoshLobes[static_cast<std::size_t>(slot)];
    for (double nm = kVisibleMinNm; nm < kVisibleMaxNm; nm += 1.0)
      ASSERT_NEAR(pdf(nm + 0.5), lobe.cdf(nm + 1.0) - lobe.cdf(nm), 1e-7) << "slot " << slot << " cell " << nm;
    const double bound = std::expm1(lobe.a_per_nm);
    for (double nm = kVisibleMinNm; nm <= kVisibleMaxNm; nm += 0.37)
      EXPECT_NEAR(pdf(nm), lobe.pdf(nm), bound * lobe.pdf(nm)) << "slot " << slot << " at " << nm;
  }
}

// The effective pdf stored with each wavelength integrates to 1 (exactly, by the whole-nm
// cell sum; float rounding of 400 cells, 1e-6) and matches a fine histogram of the pooled wavelengths: N·p̄ is their
// density. 400 bins of 1 nm, 600 000+ wavelengths (≥ 600 expected per bin); its own
// false-alarm probability 1e-3, on top of the file's 1 % for the tests above.
TEST(WavelengthSampling, ThreeLobeEffectivePdfIsNormalisedAndMatchesAFineHistogram) {
  for (int count : {3, 4}) {
    auto pdf = [count](double nm) { return wavelength_pdf(WavelengthStrategy::cosh3, count, nm); };
    EXPECT_NEAR(whole_nm_cell_sum(pdf, kVisibleMinNm, kVisibleMaxNm), 1.0, 1e-6) << count;
    constexpr int kFineBins = 400;
    constexpr long kTuples = 200000;
    std::vector<double> observed(kFineBins, 0.0), expected(kFineBins, 0.0);
    Pcg32 rng(13, 17);
    for (long t = 0; t < kTuples; ++t) {
      const double u = rng.next_double();
      std::array<double, 4> nm{};
      for (int i = 0; i < count; ++i)
        nm[static_cast<std::size_t>(i)] =
            sample_wavelength_slot(WavelengthStrategy::cosh3, i, slot_u(WavelengthStrategy::cosh3, u, i, count));
      for (int i = 0; i < count; ++i) {
        const int bin = std::min(kFineBins - 1, static_cast<int>(nm[static_cast<std::size_t>(i)] - kVisibleMinNm));
        observed[static_cast<std::size_t>(bin)] += 1.0;
      }
    }
    for (int b = 0; b < kFineBins; ++b)
      expected[static_cast<std::size_t>(b)] =
          double(kTuples) * count * whole_nm_cell_sum(pdf, kVisibleMinNm + b, kVisibleMinNm + b + 1);
    const test::ChiSquareResult r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, 1e-3) << "cosh3 N=" << count << ": " << r.message;
  }
}

// The one-call cosh3 tuple looks its per-slot constants up from a table per count; it must
// give bit for bit the wavelengths and pdfs of the slot-by-slot definition, for every count
// it accepts, and refuse the counts it has no table for.
TEST(WavelengthSampling, ThreeCoshTupleEqualsTheSlotBySlotDefinition) {
  Pcg32 rng(3, 5);
  for (int count = 1; count <= 8; ++count) {
    for (int t = 0; t < 2000; ++t) {
      const double u = t == 0 ? 0.0 : (t == 1 ? 0.5 : rng.next_double());
      std::array<float, 8> nm{}, pdf{};
      sample_three_cosh_wavelengths(u, count, nm.data(), pdf.data());
      for (int i = 0; i < count; ++i) {
        const double expected_nm =
            sample_wavelength_slot(WavelengthStrategy::cosh3, i, slot_u(WavelengthStrategy::cosh3, u, i, count));
        ASSERT_EQ(nm[static_cast<std::size_t>(i)], static_cast<float>(expected_nm)) << count << " " << i << " " << u;
        ASSERT_EQ(pdf[static_cast<std::size_t>(i)],
                  static_cast<float>(wavelength_pdf(WavelengthStrategy::cosh3, count, expected_nm)))
            << count << " " << i << " " << u;
      }
    }
  }
  std::array<float, 9> nm{}, pdf{};
  EXPECT_THROW(sample_three_cosh_wavelengths(0.5, 0, nm.data(), pdf.data()), std::invalid_argument);
  EXPECT_THROW(sample_three_cosh_wavelengths(0.5, 9, nm.data(), pdf.data()), std::invalid_argument);
}

// The one-call cosh tuple inverts the slot-by-slot definition's tanh with a float
// logarithm (atanh t = ½ ln((1 + t)/(1 − t))) and takes each pdf from that tanh (1/cosh² =
// 1 − tanh²) rather than from a cosh of the wavelength. Wavelengths: ln's float error
// (≤ 2 ulp of |ln| ≤ 3.5, plus the ratio's rounding) moves λ by ≤ 4e-5 nm, the float λ's
// own rounding ≤ 3e-5 nm: 1e-4 nm bounds both (a lost ½ is off by hundreds of nm). Pdfs:
// both are the exact density at the exact λ, so they differ by float rounding alone
// (relative 1e-6; a wrong identity, e.g. 1 + t², is off by tens of per cent).
TEST(WavelengthSampling, CoshTupleEqualsTheSlotBySlotDefinition) {
  Pcg32 rng(9, 2);
  for (int count = 1; count <= 8; ++count) {
    for (int t = 0; t < 2000; ++t) {
      const double u = t == 0 ? 0.0 : (t == 1 ? 0.5 : (t == 2 ? std::nextafter(1.0, 0.0) : rng.next_double()));
      std::array<float, 8> nm{}, pdf{};
      sample_cosh_wavelengths(u, count, nm.data(), pdf.data());
      for (int i = 0; i < count; ++i) {
        const double expected_nm =
            sample_wavelength_slot(WavelengthStrategy::cosh, i, slot_u(WavelengthStrategy::cosh, u, i, count));
        ASSERT_NEAR(nm[static_cast<std::size_t>(i)], expected_nm, 1e-4) << count << " " << i << " " << u;
        const double expected_pdf = wavelength_pdf(WavelengthStrategy::cosh, count, expected_nm);
        ASSERT_NEAR(pdf[static_cast<std::size_t>(i)], expected_pdf, 1e-6 * expected_pdf) << count << " " << i << " " << u;
      }
    }
  }
}

// AVX2 takes eight slots at a time (two tuples of four, or one of eight) with the same
// operations as SSE2's four: the same bits, and two tuples in one call are two calls'.
TEST(WavelengthSampling, CoshTuplesAreTheSameInEveryWidthAndBatch) {
  Pcg32 rng(4, 11);
  for (int count = 1; count <= 8; ++count) {
    for (int t = 0; t < 500; ++t) {
      const double u[2] = {t == 0 ? 0.0 : rng.next_double(), t == 0 ? std::nextafter(1.0, 0.0) : rng.next_double()};
      std::array<float, 8> nm_sse2{}, pdf_sse2{}, nm_widest{}, pdf_widest{};
      sample_cosh_wavelengths(u[0], count, nm_sse2.data(), pdf_sse2.data(), CoshVectorWidth::sse2);
      sample_cosh_wavelengths(u[0], count, nm_widest.data(), pdf_widest.data());
      EXPECT_EQ(nm_widest, nm_sse2) << count << " " << u[0];
      EXPECT_EQ(pdf_widest, pdf_sse2) << count << " " << u[0];
      std::array<std::array<float, 8>, 2> nm_pair{}, pdf_pair{}, nm_alone{}, pdf_alone{};
      float* const nm[2] = {nm_pair[0].data(), nm_pair[1].data()};
      float* const pdf[2] = {pdf_pair[0].data(), pdf_pair[1].data()};
      sample_cosh_wavelengths(u, count, nm, pdf);
      for (int k = 0; k < 2; ++k) {
        sample_cosh_wavelengths(u[k], count, nm_alone[k].data(), pdf_alone[k].data(), CoshVectorWidth::sse2);
        EXPECT_EQ(nm_pair[k], nm_alone[k]) << count << " " << u[k];
        EXPECT_EQ(pdf_pair[k], pdf_alone[k]) << count << " " << u[k];
      }
    }
  }
}

TEST(WavelengthSampling, HeroPartnersAreEvenlyRotated) {
  const SampledWavelengths<4> w = sample_wavelengths<4>(WavelengthStrategy::hero, 0.9);
  EXPECT_NEAR(w.wavelength_nm[0], 740.0f, 1e-3);
  EXPECT_NEAR(w.wavelength_nm[1], 440.0f, 1e-3);  // (360 + 100) mod 400 + 380
  EXPECT_NEAR(w.wavelength_nm[2], 540.0f, 1e-3);
  EXPECT_NEAR(w.wavelength_nm[3], 640.0f, 1e-3);
}

TEST(WavelengthSampling, FirstStratifiedSampleLandsNearTheLobeCentres) {
  // Stratum [4/9, 5/9) is 1/9 of each lobe's probability around its centre; with the lobe
  // densities there (0.0046–0.0056 per nm) that is about ±12 nm. Bound ±20 nm.
  for (double jitter : {0.0, 0.5, 0.999}) {
    const SampledWavelengths<3> w = sample_wavelengths<3>(WavelengthStrategy::cosh3, stratified_wavelength_u(0, jitter));
    EXPECT_NEAR(w.wavelength_nm[0], 600.0, 20.0) << jitter;
    EXPECT_NEAR(w.wavelength_nm[1], 535.0, 20.0) << jitter;
    EXPECT_NEAR(w.wavelength_nm[2], 445.0, 20.0) << jitter;
  }
}

// Lobe 0 (600 nm) is antithetic to the other two: as u grows its wavelength falls while
// lobes 1 and 2 rise, for every slot count; at u = ½ all three sit on their centres.
TEST(WavelengthSampling, ThreeCoshLobeZeroRunsAgainstTheOthers) {
  for (int count : {3, 4, 8}) {
    for (int slot = 0; slot < count; ++slot) {
      const int lobe = slot % 3;
      const double a = sample_wavelength_slot(WavelengthStrategy::cosh3, slot, slot_u(WavelengthStrategy::cosh3, 0.40, slot, count));
      const double b = sample_wavelength_slot(WavelengthStrategy::cosh3, slot, slot_u(WavelengthStrategy::cosh3, 0.41, slot, count));
      if (slot < 3) {  // the first copy of each lobe: no wrap-around between 0.40 and 0.41
        if (lobe == 0) EXPECT_LT(b, a) << count << " slot " << slot;
        else EXPECT_GT(b, a) << count << " slot " << slot;
      }
    }
    const double centres[3] = {600.0, 535.0, 445.0};
    for (int slot = 0; slot < 3; ++slot) {
      // The centre lies at u = ½ of the tabulated lobe (rounding of the 1 nm table only).
      const double nm = sample_wavelength_slot(WavelengthStrategy::cosh3, slot, slot_u(WavelengthStrategy::cosh3, 0.5, slot, count));
      EXPECT_NEAR(nm, centres[slot], 0.05) << count << " slot " << slot;
    }
  }
}

// The unbiasedness check: the mean of the estimator (1/N) Σ S(λ_i) x̄(λ_i)/p(λ_i) over M
// independent tuples must match ∫ S x̄ dλ. Reference: the 1 nm trapezoid integral; the
// Monte Carlo estimator converges to the exact integral of the (piecewise-linear) data,
// which the trapezoid rule misses by a deterministic |I_1nm − I_0.05nm| that we add to the
// bound. Statistical part: 5 standard errors (two-sided tail 6e-7 per component under the
// CLT, so 12 comparisons together false-alarm < 1e-5).
template <int N>
void expect_unbiased(WavelengthStrategy strategy, bool stratified) {
  const DenseSpectrum& d65 = standard_illuminant(StandardIlluminant::d65);
  const Vec3d reference = spectrum_to_xyz(d65);
  Vec3d fine{};
  for (int c = 0; c < 3; ++c)
    fine[c] = integrate_trapezoid([&](double nm) { return d65(nm) * cie1931_xyz_bar(nm)[c]; }, kVisibleMinNm,
                                  kVisibleMaxNm, 0.05);
  constexpr long kTuples = 180000;
  Vec3d sum{}, sum_sq{};
  Pcg32 rng(3, 5);
  for (long t = 0; t < kTuples; ++t) {
    const double u = stratified ? stratified_wavelength_u(static_cast<std::uint64_t>(t), rng.next_double())
                                : rng.next_double();
    const SampledWavelengths<N> w = sample_wavelengths<N>(strategy, u);
    const Vec3d xyz = to_xyz(sample_spectrum(d65, w), w);
    sum += xyz;
    sum_sq += xyz * xyz;
  }
  const Vec3d mean = sum / double(kTuples);
  for (int c = 0; c < 3; ++c) {
    // Stratified tuples are not independent within a cycle; their variance is at most the
    // unstratified one, so the i.i.d. standard error is a conservative bound.
    const double variance = sum_sq[c] / kTuples - mean[c] * mean[c];
    const double bound = 5.0 * std::sqrt(variance / kTuples) + std::abs(reference[c] - fine[c]);
    EXPECT_NEAR(mean[c], reference[c], bound) << wavelength_strategy_name(strategy) << " N=" << N << " c=" << c;
  }
  std::printf("%-5s N=%d%s: mean XYZ rel. error %.2e %.2e %.2e\n",
              std::string(wavelength_strategy_name(strategy)).c_str(), N, stratified ? " stratified" : "",
              mean.x / reference.x - 1, mean.y / reference.y - 1, mean.z / reference.z - 1);
}

TEST(WavelengthSampling, SpectralXyzEstimatesAreUnbiased) {
  expect_unbiased<4>(WavelengthStrategy::hero, false);
  expect_unbiased<4>(WavelengthStrategy::cosh, false);
  expect_unbiased<3>(WavelengthStrategy::cosh3, false);
  expect_unbiased<3>(WavelengthStrategy::cosh3, true);
}

TEST(WavelengthSampling, ParsesStrategyNames) {
  EXPECT_EQ(parse_wavelength_strategy("COSH3"), WavelengthStrategy::cosh3);
  EXPECT_THROW(parse_wavelength_strategy("uniform"), UsageError);
}

}  // namespace
}  // namespace prism::color
