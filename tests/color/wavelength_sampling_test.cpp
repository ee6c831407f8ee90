// Wavelength sampling strategies: chi-square goodness of fit of the sampled wavelengths
// against the pdfs they report, and unbiasedness of the spectral XYZ estimator.
#include <cmath>
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

// ∫ over [a, b] of a slot pdf by Simpson's rule on 50 panels: the pdfs are smooth (cosh
// lobes) or constant, so the quadrature error (~1e-12 relative) is far below the
// statistical resolution of the test.
double integrate_pdf(WavelengthStrategy s, int slot, double a, double b) {
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
