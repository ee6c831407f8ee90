// The thin dielectric slab (bsdf/thin_dielectric.h) against an independent evaluation:
// Fresnel from Snell's law and the s/p amplitude formulas written out here, and the slab's
// reflectance summed as the series of inter-reflections rather than the closed form.
#include "prism/bsdf/thin_dielectric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bsdf/bsdf_test_helpers.h"
#include "prism/bsdf/bsdf.h"
#include "prism/core/pcg32.h"

namespace prism::bsdf {
namespace {

// Unpolarised Fresnel reflectance from outside (Hecht, Optics, eqs. 4.34/4.40), in double.
double fresnel_reference(double cos_i, double eta) {
  const double sin_t = std::sqrt(1.0 - cos_i * cos_i) / eta;
  if (sin_t >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
  const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

// R' as the series R + T R T + T R (R R) R T + …: light reflected 0, 2, 4, … times inside
// the slab before leaving on the incident side (pbrt-v4 §9.5.1 sums it in closed form).
double slab_reflectance_series(double r) {
  const double t = 1.0 - r;
  double sum = r, inner = t * r * t;
  for (int k = 0; k < 2000 && inner > 1e-17; ++k) {
    sum += inner;
    inner *= r * r;
  }
  return sum;
}

using test_helpers::direction_in_xz_plane;

using S4 = color::SampledSpectrum<4>;

TEST(ThinDielectric, ReflectanceMatchesTheInterreflectionSeries) {
  // Float Fresnel against double: 2e-6 absolute covers float rounding of values ≤ 1.
  for (double eta : {1.33, 1.5, 2.4})
    for (double theta : {0.0, 30.0, 60.0, 80.0, 89.0}) {
      const double cos_i = std::cos(theta * std::numbers::pi / 180.0);
      const double expected = slab_reflectance_series(fresnel_reference(cos_i, eta));
      const ThinDielectric<4> slab{S4(static_cast<float>(eta))};
      EXPECT_NEAR(slab.reflectance(static_cast<float>(cos_i))[0], expected, 2e-6) << eta << " at " << theta << "°";
    }
  // Normal incidence, η = 1.5: R = 0.04, R' = 2R/(1 + R) = 0.0769231 (the closed form
  // simplifies to this for any R).
  EXPECT_NEAR(ThinDielectric<4>{S4(1.5f)}.reflectance(1.0f)[0], 0.08 / 1.04, 1e-6);
}

TEST(ThinDielectric, SamplesMirrorAndStraightThroughAndConservesEnergy) {
  // Spectral IOR: every channel its own η (strongly different, as a test). Each sample's
  // weight f |cos θi| / pdf, averaged, is R' + T' = 1 per channel (white furnace, no
  // absorption); the reflected/transmitted fractions match R', T'. 4 standard errors.
  S4 eta;
  const float etas[4] = {1.2f, 1.5f, 1.9f, 2.6f};
  for (std::size_t c = 0; c < 4; ++c) eta[c] = etas[c];
  const ThinDielectric<4> slab{eta};
  const Bsdf<4> bsdf{slab};
  EXPECT_TRUE(bsdf.is_specular());
  EXPECT_FALSE(bsdf.is_dispersive());
  for (const Vec3f& wo : {direction_in_xz_plane(10), direction_in_xz_plane(60), direction_in_xz_plane(85), -direction_in_xz_plane(40)}) {
    const S4 r = slab.reflectance(wo.z);
    Pcg32 rng(7, 3);
    constexpr int kN = 200'000;
    double sum[4] = {}, sum2[4] = {}, reflected[4] = {}, reflected2[4] = {};
    for (int i = 0; i < kN; ++i) {
      const auto s = bsdf.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
      ASSERT_TRUE(s);
      ASSERT_TRUE(s->is_specular);
      EXPECT_EQ(s->eta, 1.0f);
      if (s->is_transmission) {
        EXPECT_EQ(s->wi.x, -wo.x);  // straight through: no refraction offset
        EXPECT_EQ(s->wi.y, -wo.y);
        EXPECT_EQ(s->wi.z, -wo.z);
      } else {
        EXPECT_EQ(s->wi.x, -wo.x);
        EXPECT_EQ(s->wi.z, wo.z);
      }
      for (int c = 0; c < 4; ++c) {
        const double w = double(s->f[c]) * std::abs(s->wi.z) / s->pdf;
        sum[c] += w;
        sum2[c] += w * w;
        if (!s->is_transmission) reflected[c] += w, reflected2[c] += w * w;
      }
      if (::testing::Test::HasFailure()) return;
    }
    for (int c = 0; c < 4; ++c) {
      const double mean = sum[c] / kN, se = std::sqrt(std::max(0.0, sum2[c] / kN - mean * mean) / kN);
      EXPECT_NEAR(mean, 1.0, 4.0 * se + 1e-6) << "channel " << c << " wo.z " << wo.z;
      // The reflected part has its own (binomial-like) variance; the total weight's standard
      // error is near zero when the channels' R' are alike, so it cannot bound this one.
      const double reflected_mean = reflected[c] / kN;
      const double reflected_se =
          std::sqrt(std::max(0.0, reflected2[c] / kN - reflected_mean * reflected_mean) / kN);
      EXPECT_NEAR(reflected_mean, r[c], 4.0 * reflected_se + 1e-6) << "channel " << c << " wo.z " << wo.z;
      EXPECT_NEAR(r[c] + (1.0f - r[c]), 1.0, 1e-7);
    }
  }
}

TEST(ThinDielectric, IsADeltaLobeWithoutDensity) {
  const ThinDielectric<4> slab{S4(1.5f)};
  EXPECT_EQ(slab.pdf(direction_in_xz_plane(20), -direction_in_xz_plane(20)), 0.0f);
  EXPECT_TRUE(slab.eval(direction_in_xz_plane(20), -direction_in_xz_plane(20)).is_black());
  EXPECT_FALSE(slab.sample(Vec3f(1, 0, 0), 0.5f, Vec2f(0.5f, 0.5f)));  // grazing: no sample
}

}  // namespace
}  // namespace prism::bsdf
