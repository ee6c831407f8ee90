// Jakob–Hanika 2019 upsampling: our fitter, the embedded coefficient tables (regenerated
// samples must match), and the RGB → spectrum → XYZ → RGB round trip in ΔE*ab.
#include <cmath>
#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>
#include <string>

#include <gtest/gtest.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/cielab.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"
#include "prism/color/jakob_hanika_fit.h"
#include "prism/color/jakob_hanika_table.h"
#include "prism/color/sigmoid_polynomial.h"
#include "prism/core/pcg32.h"

namespace prism::color {
namespace {

TEST(JakobHanikaFit, GreyIsFlatAndSaturatedColoursConverge) {
  const JakobHanikaFitter fitter(standard_illuminant(StandardIlluminant::d65));
  const JakobHanikaFitResult grey = fitter.fit(fitter.white_xyz() * 0.18, {0, 0, 0});
  EXPECT_TRUE(grey.converged);
  const SigmoidPolynomial s = to_wavelength_nm(grey.coefficients);
  EXPECT_NEAR(s(400.0), 0.18, 1e-6);
  EXPECT_NEAR(s(700.0), 0.18, 1e-6);
  const ColorSpace& srgb = color_space("srgb");
  const JakobHanikaFitResult orange = fitter.fit(srgb.rgb_to_xyz * Vec3d(0.9, 0.4, 0.05), {0, 0, 0});
  EXPECT_TRUE(orange.converged) << orange.delta_e;
  // Normalised ↔ nm coefficients describe the same polynomial.
  const NormalizedCoefficients c{3.0, -2.0, 0.5};
  const SigmoidPolynomial nm = to_wavelength_nm(c);
  const double t = (512.0 - 380.0) / 400.0;
  EXPECT_NEAR(nm(512.0), sigmoid_jakob_hanika((c[0] * t + c[1]) * t + c[2]), 1e-12);
}

TEST(JakobHanikaTable, EmbeddedTablesMatchARegeneratedSample) {
  // The tables are generated at build time; refit a spread of grid nodes from scratch and
  // compare spectra. Both fits stop at 1e-6 ΔE and the 3×3 problem has a unique solution
  // near a converged one; the table stores float coefficients (relative 6e-8) whose
  // cancellation in c₀λ² + c₁λ + c₂ costs < 1e-4 in s. Bound: 1e-3.
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const ColorSpace& space = color_space(name);
    const JakobHanikaTable& table = JakobHanikaTable::get(name);
    const JakobHanikaFitter fitter(standard_illuminant(StandardIlluminant::e));
    const int res = table.resolution();
    for (const auto& [l, k, j, i] : {std::array{0, res / 2, res / 3, res / 4}, std::array{1, res - 1, 0, res - 1},
                                      std::array{2, res / 5, res / 2, res / 2}, std::array{0, 3, 1, 2}}) {
      const Vec3d rgb = jakob_hanika_grid_rgb(l, k, j, i, res);
      const JakobHanikaFitResult fresh = fitter.fit(jakob_hanika_target_xyz_matrix(space) * rgb, {0, 0, 0}, 200);
      if (!fresh.converged) continue;  // out-of-locus nodes have no unique best fit to compare
      const SigmoidPolynomial a = table.lookup(rgb), b = to_wavelength_nm(fresh.coefficients);
      for (double nm = 380.0; nm <= 780.0; nm += 5.0) EXPECT_NEAR(a(nm), b(nm), 1e-3) << name << " " << rgb.x;
    }
  }
}

struct RoundTrip {
  double mean = 0.0, max = 0.0, p95 = 0.0;
  Vec3d worst{};
};

RoundTrip round_trip(const std::string& name, const Mat3& from_srgb) {
  const ColorSpace& space = color_space(name);
  const JakobHanikaTable& table = JakobHanikaTable::get(name);
  // As a spectral render sees it: under E, adapted to the space's white.
  const DenseSpectrum& illuminant = standard_illuminant(StandardIlluminant::e);
  const Mat3 film_to_rgb = spectral_xyz_to_rgb_matrix(space);
  const Vec3d white = white_XYZ(space);
  RoundTrip r;
  std::vector<double> errors;
  int count = 0;
  constexpr int kLevels = 9;
  for (int a = 0; a < kLevels; ++a)
    for (int b = 0; b < kLevels; ++b)
      for (int c = 0; c < kLevels; ++c) {
        const Vec3d srgb = Vec3d(a, b, c) / double(kLevels - 1);
        const Vec3d rgb = min(max(from_srgb * srgb, Vec3d(0.0)), Vec3d(1.0));
        const Vec3d xyz = reflectance_to_xyz(table.lookup(rgb), illuminant);
        const Vec3d back = film_to_rgb * xyz;
        const double de = delta_e76(xyz_to_lab(space.rgb_to_xyz * rgb, white), xyz_to_lab(space.rgb_to_xyz * back, white));
        r.mean += de;
        errors.push_back(de);
        ++count;
        if (de > r.max) r.max = de, r.worst = rgb;
      }
  r.mean /= count;
  std::sort(errors.begin(), errors.end());
  r.p95 = errors[errors.size() * 95 / 100];
  std::printf("Jakob-Hanika %-8s (table %d^3): round trip dE76 mean %.4f, p95 %.4f, max %.4f at rgb (%.3f %.3f %.3f)\n",
              name.c_str(), table.resolution(), r.mean, r.p95, r.max, r.worst.x, r.worst.y, r.worst.z);
  return r;
}

// Round trip RGB → spectrum → XYZ under the space's white → RGB for in-gamut colours: a
// 9³ grid over the sRGB cube, expressed in each space (so every colour is a physically
// realisable reflectance; the wide-gamut corners are not). Jakob & Hanika report errors
// well under 1 ΔE for such colours; what remains is the table's trilinear interpolation
// error (the fits themselves converge to 1e-6 ΔE) plus the 2e-4 offset between the
// tabulated D65 and the spaces' printed D65 xy (< 0.05 ΔE).
// In acescg and rec2020 many in-gamut sRGB colours lie close to the optimal-colour
// boundary (the edge of what a reflectance can reach), where the sigmoid coefficients
// grow without bound, and cells there touch nodes beyond it. The generator (see
// jakob_hanika_fit.h/.cpp) spaces all three axes by smoothstep and stores a reachable
// neighbour's coefficients at unreachable nodes; with the paper's spacing and raw fits at
// those nodes (|c| up to 1e15) the worst colours here were off by 12.9 ΔE (acescg) and
// 22.3 ΔE (rec2020). Measured at 32³ with the E-relative tables (jakob_hanika_fit.h) and
// the round trip under E: srgb mean 0.045 / p95 0.12 / max 0.25; acescg 0.18 / 0.50 / 2.50
// (a dark blue); rec2020 0.15 / 0.35 / 1.80 (a bright yellow). (The D65 tables under D65
// measured 0.046 / 0.12 / 0.25, 0.19 / 0.53 / 2.80 and 0.16 / 0.36 / 2.22.) The remaining
// max is the interpolation error of the few cells that straddle the boundary. The table is
// deterministic (every column and slice is fitted sequentially), so only a change to the
// fitter, the spacing or the lookup moves these numbers: the bounds leave 1.5–2× headroom
// on means and percentiles and 20 % on the acescg max (3.0), and a return of the poisoned
// cells (errors of 10+ ΔE) fails.
TEST(JakobHanikaTable, RoundTripErrorOfInGamutColoursIsBounded) {
  const ColorSpace& srgb = color_space("srgb");
  const RoundTrip s = round_trip("srgb", Mat3::identity());
  EXPECT_LT(s.mean, 0.1);
  EXPECT_LT(s.max, 0.5);
  for (const std::string name : {"acescg", "rec2020"}) {
    const RoundTrip r = round_trip(name, conversion_matrix(srgb, color_space(name)));
    EXPECT_LT(r.mean, 0.3) << name;
    EXPECT_LT(r.p95, 0.75) << name;
    EXPECT_LT(r.max, 3.0) << name;
  }
}

// The colours of tests/render/upsampled_colour_render_test.cpp, looked up and filmed as a
// spectral render films them under a white light (E, adapted to D65): the table reproduces
// each albedo per channel to its interpolation error. The paper's D65 fit, seen this way,
// missed the Cornell walls by 0.024–0.045; an E-relative fit at the exact colour misses by
// < 1e-6 (the fitter's tolerance), so what is left is trilinear interpolation between
// nodes of the 32³ grid — measured 1.43e-3 at worst here (deterministic); bound 2e-3.
TEST(JakobHanikaTable, AlbedosFilmAsThemselvesUnderAWhiteLight) {
  const ColorSpace& srgb = color_space("srgb");
  const JakobHanikaTable& table = JakobHanikaTable::get("srgb");
  const Mat3 film_to_srgb = spectral_xyz_to_rgb_matrix(srgb);
  const DenseSpectrum& e = standard_illuminant(StandardIlluminant::e);
  double worst = 0.0;
  for (const Vec3d albedo : {Vec3d(0.63, 0.065, 0.05), Vec3d(0.14, 0.45, 0.091), Vec3d(0.725, 0.71, 0.68),
                             Vec3d(0.022, 0.111, 0.044), Vec3d(0.05, 0.05, 0.5), Vec3d(0.9, 0.4, 0.05),
                             Vec3d(0.18, 0.18, 0.18)}) {
    const Vec3d filmed = film_to_srgb * reflectance_to_xyz(table.lookup(albedo), e);
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(filmed[c] - albedo[c]));
      EXPECT_NEAR(filmed[c], albedo[c], 2e-3) << albedo.x << " " << albedo.y << " " << albedo.z << " channel " << c;
    }
  }
  std::printf("Jakob-Hanika srgb under E, worst channel error over the render test's albedos: %.2e\n", worst);
}

// Every lookup in the whole cube — including the wide-gamut colours no reflectance can
// reach, whose nodes hold a neighbour's coefficients — must give finite coefficients and a
// reflectance in [0, 1] (the sigmoid bounds it; a NaN or infinite coefficient would not).
TEST(JakobHanikaTable, EveryLookupIsAValidReflectance) {
  constexpr int kLevels = 17;
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const JakobHanikaTable& table = JakobHanikaTable::get(name);
    int failures = 0;
    for (int a = 0; a < kLevels; ++a)
      for (int b = 0; b < kLevels; ++b)
        for (int c = 0; c < kLevels; ++c) {
          if (a == b && b == c) continue;  // greys: exact constants, c₂ = ±∞ at 0 and 1
          const Vec3d rgb = Vec3d(a, b, c) / double(kLevels - 1);
          const SigmoidPolynomial s = table.lookup(rgb);
          bool ok = std::isfinite(s.c0) && std::isfinite(s.c1) && std::isfinite(s.c2);
          for (double nm = 380.0; nm <= 780.0; nm += 5.0) ok = ok && s(nm) >= 0.0 && s(nm) <= 1.0;
          if (!ok && ++failures <= 5) ADD_FAILURE() << name << " rgb " << rgb.x << " " << rgb.y << " " << rgb.z;
        }
    EXPECT_EQ(failures, 0) << name;
  }
}

TEST(JakobHanikaTable, GreysAreExactAndUnknownSpacesAreRejected) {
  const SigmoidPolynomial grey = JakobHanikaTable::get("sRGB").lookup({0.5, 0.5, 0.5});
  EXPECT_DOUBLE_EQ(grey(400.0), 0.5);
  EXPECT_DOUBLE_EQ(JakobHanikaTable::get("srgb").lookup({1, 1, 1})(550.0), 1.0);
  EXPECT_THROW(JakobHanikaTable::get("display-p3"), UsageError);
  EXPECT_THROW(JakobHanikaTable::get("nonsense"), UsageError);
}

// The cells a lookup interpolates in are std::upper_bound's over the axis' nodes (the
// guide tables only skip the search): at, just below and just above every node, between
// nodes, at the ends, and for random values, along both kinds of axis of every table.
TEST(JakobHanikaTable, GuidedCellsAreTheSearchsCells) {
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const JakobHanikaTable& table = JakobHanikaTable::get(name);
    const int res = table.resolution();
    for (const bool chroma : {true, false}) {
      const std::vector<float>& nodes = chroma ? table.chroma_nodes() : table.scale_nodes();
      ASSERT_EQ(nodes.size(), static_cast<std::size_t>(res));
      std::vector<double> vs = {0.0, 1.0, -0.5, 2.0, 1e-9, 0.999999};
      for (const float n : nodes) {
        vs.insert(vs.end(), {n, std::nextafter(n, 0.0f), std::nextafter(n, 2.0f), double(n) + 1e-12});
      }
      for (int i = 0; i + 1 < res; ++i) vs.push_back(0.5 * (double(nodes[i]) + nodes[i + 1]));
      for (int g = 0; g <= 4096; ++g) vs.push_back(g / 4096.0);
      Pcg32 rng(17, 18);
      for (int i = 0; i < 20000; ++i) vs.push_back(rng.next_double());
      for (const double v : vs) {
        const int expected =
            std::clamp(static_cast<int>(std::upper_bound(nodes.begin(), nodes.end(), float(v)) - nodes.begin()) - 1, 0,
                       res - 2);
        ASSERT_EQ(chroma ? table.chroma_cell(v) : table.scale_cell(v), expected) << name << " " << chroma << " " << v;
      }
    }
  }
}

// The renderer's single-precision sigmoid against the definition in long double, written
// in the same cancellation-free tail form min(S, 1 − S) = 1/(2r(r + |x|)) so the reference
// is exact to ~1e-19 on both sides. Tolerance: the float path rounds x once (the tail's
// relative sensitivity to x is at most 2, so ≤ 2 × 6e-8) and then makes six roundings of
// ≤ 6e-8 each, ≤ 5e-7 in all, asserted as 1e-6 relative on the tail; on the bright side
// S = 1 − tail carries that tail error and is rounded once more, to float's step at 1
// (1.2e-7 absolute).
TEST(JakobHanikaSigmoid, SinglePrecisionFormIsAccurateOnBothSides) {
  auto reference_tail = [](long double x) {
    const long double r = std::sqrt(1.0L + x * x);
    return 1.0L / (2.0L * r * (r + std::fabs(x)));
  };
  int checked = 0;
  for (double magnitude = 1e-6; magnitude < 1e6; magnitude *= 1.07) {
    for (const double x : {magnitude, -magnitude}) {
      const float xf = static_cast<float>(x);
      const float s = sigmoid_jakob_hanika_float(xf);
      const long double tail = reference_tail(xf);  // the error of rounding x is asserted below
      if (x < 0.0) {
        ASSERT_NEAR(s, static_cast<double>(tail), 1e-6 * static_cast<double>(tail)) << x;
      } else {
        ASSERT_NEAR(s, static_cast<double>(1.0L - tail), 1e-6 * static_cast<double>(tail) + 1.2e-7) << x;
      }
      // The double definition agrees wherever it is itself accurate (no cancellation).
      if (std::abs(x) < 10.0) {
        ASSERT_NEAR(s, sigmoid_jakob_hanika(x), 1e-6 * sigmoid_jakob_hanika(x) + 1.2e-7) << x;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 400);
  // The constant spectra 0 and 1 (c₂ = ∓∞) stay exactly 0 and 1; x = 0 is ½; NaN is NaN.
  EXPECT_EQ(sigmoid_jakob_hanika_float(-INFINITY), 0.0f);
  EXPECT_EQ(sigmoid_jakob_hanika_float(INFINITY), 1.0f);
  EXPECT_EQ(sigmoid_jakob_hanika_float(0.0f), 0.5f);
  EXPECT_TRUE(std::isnan(sigmoid_jakob_hanika_float(NAN)));
}

// evaluate_sigmoid_polynomial (the renderer's N-wavelength path) against operator() for
// every table's colours across the visible range: within the tolerance above, plus 1e-12
// absolute where operator()'s own ½ + x/(2r) cancels (it keeps 1e-16 absolute there).
TEST(JakobHanikaSigmoid, NWavelengthEvaluationMatchesTheDefinition) {
  constexpr int kLevels = 9;
  int checked = 0;
  for (const std::string name : {"srgb", "acescg", "rec2020"}) {
    const JakobHanikaTable& table = JakobHanikaTable::get(name);
    for (int a = 0; a < kLevels; ++a)
      for (int b = 0; b < kLevels; ++b)
        for (int c = 0; c < kLevels; ++c) {
          const SigmoidPolynomial poly = table.lookup(Vec3d(a, b, c) / double(kLevels - 1));
          for (float first = 380.0f; first <= 780.0f; first += 37.0f) {
            const std::array<float, 4> nm{first, std::fmod(first + 100.3f, 400.0f) + 380.0f,
                                          std::fmod(first + 201.7f, 400.0f) + 380.0f, 780.0f - (first - 380.0f)};
            const std::array<float, 4> scaled = evaluate_sigmoid_polynomial(poly, nm, 2.5f);
            const std::array<float, 4> s = evaluate_sigmoid_polynomial(poly, nm);
            // The 3- and 8-wavelength forms (the renderer's other N) give the same bits,
            // and so does the scalar sigmoid (the SIMD path makes the same operations).
            const std::array<float, 3> three = evaluate_sigmoid_polynomial(poly, std::array<float, 3>{nm[0], nm[1], nm[2]});
            const std::array<float, 8> eight = evaluate_sigmoid_polynomial(
                poly, std::array<float, 8>{nm[0], nm[1], nm[2], nm[3], nm[3], nm[2], nm[1], nm[0]});
            for (std::size_t i = 0; i < 4; ++i) {
              const double nm_i = nm[i];
              ASSERT_EQ(s[i], sigmoid_jakob_hanika_float(static_cast<float>((poly.c0 * nm_i + poly.c1) * nm_i + poly.c2)));
              ASSERT_EQ(eight[i], s[i]);
              ASSERT_EQ(eight[7 - i], s[i]);
              if (i < 3) {
                ASSERT_EQ(three[i], s[i]);
              }
            }
            for (std::size_t i = 0; i < 4; ++i) {
              const double expected = poly(nm[i]);
              const double tolerance =
                  expected < 0.5 ? 1e-6 * expected + 1e-12 : 1.2e-7 + 1e-6 * (1.0 - expected);
              ASSERT_NEAR(s[i], expected, tolerance) << name << " " << a << b << c << " at " << nm[i] << " nm";
              ASSERT_EQ(scaled[i], 2.5f * s[i]);
              ++checked;
            }
          }
        }
  }
  EXPECT_EQ(checked, 3 * 9 * 9 * 9 * 11 * 4);
}

}  // namespace
}  // namespace prism::color
