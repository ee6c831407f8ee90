// Next-event sampling of an emissive triangle: the sampled points follow the density that
// triangle_light_pdf reports (chi-square), that density integrates to 1 over the
// triangle, sampling and pdf agree point by point, and the solid-angle strategies fall
// back to area sampling exactly where documented.
#include "prism/scene/triangle_light_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "prism/core/pcg32.h"
#include "prism/sampling/spherical_triangle.h"
#include "support/chi_square.h"

namespace prism {
namespace {

constexpr int kTriangleLightChiSquareTests = 7;  // test::kAlphaTotal is Šidák-split over these

TriangleLight make_light(const Vec3f& p0, const Vec3f& p1, const Vec3f& p2, bool two_sided = false) {
  TriangleLight l;
  l.p0 = p0;
  l.e1 = p1 - p0;
  l.e2 = p2 - p0;
  const Vec3f n = cross(l.e1, l.e2);
  l.normal = normalize(n);
  l.area = 0.5f * length(n);
  l.two_sided = two_sided;
  return l;
}

// One half of the Cornell box's ceiling light (emitting downwards, -y).
TriangleLight cornell_light_half() {
  return make_light({213, 548.8f, 227}, {343, 548.8f, 332}, {213, 548.8f, 332});
}

struct Receiver {
  Vec3f position, normal;
};

// Points on the triangle by the square (s, t) of the uniform map, b2 = 1 − √s,
// b1 = t √s: area-preserving, so dA = area · ds dt.
Vec3f point_at(const TriangleLight& l, double s, double t) {
  const double r = std::sqrt(s);
  return l.p0 + l.e1 * static_cast<float>(t * r) + l.e2 * static_cast<float>(1.0 - r);
}

// ∫ over the square cell of p_ω(x) · cos θ_light / r² · area: the probability mass of the
// cell under the density that triangle_light_pdf reports (solid angle → area measure).
double cell_mass(const TriangleLight& l, TriangleLightSampling strategy, const Receiver& rx, double s0, double t0,
                 double ds, double dt, int sub) {
  double sum = 0.0;
  for (int a = 0; a < sub; ++a)
    for (int b = 0; b < sub; ++b) {
      const Vec3f p = point_at(l, s0 + ds * (a + 0.5) / sub, t0 + dt * (b + 0.5) / sub);
      const Vec3f d = p - rx.position;
      const double d2 = length_squared(Vec3d(d));
      const double cos_light = std::abs(dot(Vec3d(l.normal), Vec3d(d))) / std::sqrt(d2);
      sum += triangle_light_pdf(l, strategy, rx.position, rx.normal, p) * cos_light / d2;
    }
  return sum * l.area * (ds / sub) * (dt / sub);
}

void expect_samples_follow_pdf(const TriangleLight& l, TriangleLightSampling strategy, const Receiver& rx,
                               unsigned long long seed) {
  constexpr int kBins = 16;
  constexpr long kSamples = 200'000;
  std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, 0.0);
  Pcg32 rng(seed, 3);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = sample_triangle_light(l, strategy, rx.position, rx.normal, Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_TRUE(s.has_value());
    // The sample's own density must be the one the pdf function gives its point (MIS
    // uses the latter); float rounding of the direction and the inverse map only.
    const float pdf = triangle_light_pdf(l, strategy, rx.position, rx.normal, s->position);
    ASSERT_NEAR(s->pdf_sr, pdf, 1e-3f * pdf);
    // uv comes from the barycentrics: they must give the point.
    const Vec3f from_b = l.p0 + l.e1 * s->barycentric.x + l.e2 * s->barycentric.y;
    ASSERT_LT(length(from_b - s->position), 1e-3f);
    ASSERT_LT(length(normalize(s->position - rx.position) - s->wi), 1e-4f);
    const double b2 = std::clamp(double(s->barycentric.y), 0.0, 1.0);
    const double sq = 1.0 - b2;
    const double t = sq > 0.0 ? s->barycentric.x / sq : 0.0;
    const int is = std::clamp(static_cast<int>(sq * sq * kBins), 0, kBins - 1);
    const int it = std::clamp(static_cast<int>(t * kBins), 0, kBins - 1);
    observed[static_cast<std::size_t>(is * kBins + it)] += 1.0;
  }
  for (int is = 0; is < kBins; ++is)
    for (int it = 0; it < kBins; ++it)
      // 8² midpoints per cell: the densities are smooth on the triangle (no edges inside
      // a cell), so the quadrature error is O(1e-4) relative, far below the test's noise.
      expected[static_cast<std::size_t>(is * kBins + it)] =
          kSamples * cell_mass(l, strategy, rx, double(is) / kBins, double(it) / kBins, 1.0 / kBins, 1.0 / kBins, 8);
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kTriangleLightChiSquareTests)) << r.message;
}

// Below the light on the floor, beside it high on a wall, just under the ceiling next to it
// (grazing, where the receiver cosine varies most across the light).
const Receiver kFloor{{278, 0, 279}, {0, 1, 0}};
const Receiver kWall{{0.5f, 480, 279}, {1, 0, 0}};
const Receiver kUnderCeiling{{180, 530, 240}, {0, -1, 0}};
// A receiver whose normal makes the bilinear weights very unequal.
const Receiver kTilted{{260, 420, 300}, {0.8f, 0.0f, 0.6f}};

TEST(TriangleLightSampling, SolidAngleSamplesFollowTheirPdf) {
  expect_samples_follow_pdf(cornell_light_half(), TriangleLightSampling::solid_angle, kFloor, 1);
  expect_samples_follow_pdf(cornell_light_half(), TriangleLightSampling::solid_angle, kUnderCeiling, 2);
}

TEST(TriangleLightSampling, CosineWarpedSamplesFollowTheirPdf) {
  for (const Receiver& rx : {kFloor, kWall, kUnderCeiling, kTilted})
    expect_samples_follow_pdf(cornell_light_half(), TriangleLightSampling::solid_angle_cosine, rx, 5);
}

TEST(TriangleLightSampling, TwoSidedTriangleIsSampledFromBehind) {
  const TriangleLight l = make_light({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, true);
  const Receiver behind{{0.3f, 0.2f, -0.8f}, {0.0f, 0.6f, 0.8f}};
  expect_samples_follow_pdf(l, TriangleLightSampling::solid_angle_cosine, behind, 7);
  // One-sided, the same triangle cannot light that point.
  const TriangleLight one_sided = make_light({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_FALSE(sample_triangle_light(one_sided, TriangleLightSampling::solid_angle_cosine, behind.position,
                                     behind.normal, Vec2f(0.3f, 0.4f)));
  EXPECT_EQ(triangle_light_pdf(one_sided, TriangleLightSampling::solid_angle_cosine, behind.position, behind.normal,
                               Vec3f(0.2f, 0.2f, 0.0f)),
            0.0f);
}

TEST(TriangleLightSampling, PdfIntegratesToOneOverTheTriangle) {
  const TriangleLight l = cornell_light_half();
  for (TriangleLightSampling strategy :
       {TriangleLightSampling::area, TriangleLightSampling::solid_angle, TriangleLightSampling::solid_angle_cosine})
    for (const Receiver& rx : {kFloor, kWall, kUnderCeiling, kTilted}) {
      // 64² cells × 4² midpoints; smooth integrand: the quadrature error is ~1e-5, and
      // float pdfs add ~1e-6 relative per point.
      double total = 0.0;
      for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) total += cell_mass(l, strategy, rx, i / 64.0, j / 64.0, 1 / 64.0, 1 / 64.0, 4);
      EXPECT_NEAR(total, 1.0, 1e-3) << static_cast<int>(strategy);
    }
}

TEST(TriangleLightSampling, UniformSolidAngleDensityIsOneOverTheSolidAngle) {
  // Ω by quadrature of cos θ_light / r² over the triangle, independent of the closed form.
  const TriangleLight l = cornell_light_half();
  double omega = 0.0;
  constexpr int kN = 256;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const Vec3d d = Vec3d(point_at(l, (i + 0.5) / kN, (j + 0.5) / kN) - kFloor.position);
      const double d2 = length_squared(d);
      omega += std::abs(dot(Vec3d(l.normal), d)) / (d2 * std::sqrt(d2));
    }
  omega *= double(l.area) / (kN * kN);
  const float pdf = triangle_light_pdf(l, TriangleLightSampling::solid_angle, kFloor.position, kFloor.normal,
                                       point_at(l, 0.3, 0.6));
  EXPECT_NEAR(pdf * omega, 1.0, 1e-4);
}

TEST(TriangleLightSampling, TinyAndHugeSolidAnglesFallBackToAreaSampling) {
  const TriangleLight l = cornell_light_half();
  // Far away: Ω ≈ 6800 mm² / (50 m)² ≈ 3e-6 sr < kMinSolidAngleSr.
  const Vec3f far(278, -50000, 279), on_light = point_at(l, 0.4, 0.5);
  const float area_pdf = triangle_light_pdf(l, TriangleLightSampling::area, far, Vec3f(0, 1, 0), on_light);
  EXPECT_EQ(triangle_light_pdf(l, TriangleLightSampling::solid_angle_cosine, far, Vec3f(0, 1, 0), on_light),
            area_pdf);
  // 1e-3 below the light's centre: Ω → 2π, above kMaxSolidAngleSr.
  const Vec3f close = point_at(l, 0.5, 0.5) - Vec3f(0, 1e-3f, 0);
  const SphericalTriangle t = make_spherical_triangle(Vec3d(close), Vec3d(l.p0), Vec3d(l.p0 + l.e1), Vec3d(l.p0 + l.e2));
  ASSERT_GT(t.solid_angle_sr, kMaxSolidAngleSr);
  EXPECT_EQ(triangle_light_pdf(l, TriangleLightSampling::solid_angle_cosine, close, Vec3f(0, -1, 0), on_light),
            triangle_light_pdf(l, TriangleLightSampling::area, close, Vec3f(0, -1, 0), on_light));
}

}  // namespace
}  // namespace prism
