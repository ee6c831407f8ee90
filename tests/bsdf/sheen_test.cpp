// Sheen (bsdf/sheen.h): the tabulated albedo against Monte Carlo, white furnaces (exactly 1
// over a white Lambertian base for any sheen colour, also where the fitted lobe alone would
// reflect more than it receives), the per-channel albedo scaling over coloured bases, and
// sample() against pdf() and eval(), with and without a clear coat on top.
// Statistical bounds are 4 standard errors (two-sided false-alarm rate 6e-5 per check).
#include "prism/bsdf/sheen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "bsdf/bsdf_test_helpers.h"
#include "prism/bsdf/bsdf.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"

namespace prism::bsdf {
namespace {

using S3 = color::SampledSpectrum<3>;
using test_helpers::direction_at;
using test_helpers::Estimate;
using test_helpers::monte_carlo;
using test_helpers::rgb;

// ∫ f_sheen/c cos θi dωi from wo, estimated independently of the table (a midpoint rule in
// (√cos θi, φ)) and of the sheen's sampler (uniform): cosine-weighted directions, f π each.
Estimate sheen_albedo_by_cosine_sampling(float r, const Vec3f& wo, long n, unsigned long long seed) {
  return monte_carlo(n, seed, [&](Pcg32& rng) {
    const Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    return double(charlie_sheen_brdf(wo, wi, r * r)) * std::numbers::pi;
  });
}

// Table error: between nodes, bilinear interpolation of the 32² table (nodes at (i/31)² in
// cos θ) against an independent estimate. Measured (the printout below): at most 0.0021 up
// to 80° (estimates' σ ≤ 0.002) and 0.011 at 88°, where E climbs fastest (σ there up to
// 0.011, so mostly the estimate's own noise). Bounds: 4σ plus about 3 × those, also used by
// the furnaces.
constexpr double kSheenTableError = 0.006, kSheenTableErrorGrazing = 0.04;
double sheen_table_error(double theta_deg) { return theta_deg > 80.0 ? kSheenTableErrorGrazing : kSheenTableError; }

TEST(Sheen, TabulatedAlbedoMatchesIndependentEstimate) {
  unsigned long long seed = 1;
  for (float r : {0.1f, 0.23f, 0.5f, 0.77f, 1.0f})
    for (double theta : {0.0, 33.3, 61.0, 80.0, 88.0}) {
      const Vec3f wo = direction_at(theta, 25.0);
      const Estimate e = sheen_albedo_by_cosine_sampling(r, wo, 400'000, ++seed);
      const double table = sheen_directional_albedo(wo.z, r);
      EXPECT_NEAR(table, e.mean, 4.0 * e.stderr_ + sheen_table_error(theta)) << "r=" << r << " theta=" << theta;
      std::printf("sheen albedo r=%.2f theta=%4.1f: table %.5f, estimate %.5f ± %.5f\n", r, theta, table, e.mean,
                  e.stderr_);
    }
  // Roughness below the floor is the floor's.
  EXPECT_EQ(sheen_directional_albedo(0.3f, 0.0f), sheen_directional_albedo(0.3f, kMinSheenPerceptualRoughness));
}

// The BSDF's albedo at wo, channel c, through its own sampler.
Estimate albedo_by_bsdf_sampling(const Bsdf<3>& b, const Vec3f& wo, int channel, long n, unsigned long long seed) {
  return monte_carlo(n, seed, [&](Pcg32& rng) {
    const auto s = b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    return s ? double(s->f[channel]) * std::abs(s->wi.z) / s->pdf : 0.0;
  });
}

// A white Lambertian base under a white sheen: c Ê + (1 − c Ê) · 1 = 1 at every angle and
// roughness, including r = 0.1 at 85°, where E > 1 and the lobe is normalised. Bound: 4σ
// plus the table's error.
TEST(Sheen, WhiteFurnaceOverWhiteLambertIsOne) {
  unsigned long long seed = 100;
  for (float r : {0.0f, 0.1f, 0.4f, 1.0f})
    for (double theta : {0.0, 45.0, 80.0, 85.0}) {
      Bsdf<3> b{Lambertian<3>{S3(1.0f)}};
      b.sheen = Sheen<3>::make(S3(1.0f), r);
      const Vec3f wo = direction_at(theta, 70.0);
      const Estimate e = albedo_by_bsdf_sampling(b, wo, 0, 200'000, ++seed);
      EXPECT_NEAR(e.mean, 1.0, 4.0 * e.stderr_ + sheen_table_error(theta)) << "r=" << r << " theta=" << theta;
    }
}

// Over a coloured base, per channel: c Ê + (1 − c Ê) ρ, with Ê = min(E, 1) from the table.
// So the sheen's colour shows where it is strong and the base's elsewhere, and a white
// furnace stays at 1 whatever the sheen's colour (channel 2's c = 0: the base alone).
TEST(Sheen, EachChannelKeepsWhatTheSheenDoesNotReflect) {
  const S3 rho = rgb(0.2f, 0.5f, 1.0f), c = rgb(0.9f, 0.3f, 0.0f);
  unsigned long long seed = 200;
  for (float r : {0.3f, 0.8f})
    for (double theta : {10.0, 60.0, 82.0}) {
      Bsdf<3> b{Lambertian<3>{rho}};
      b.sheen = Sheen<3>::make(c, r);
      const Vec3f wo = direction_at(theta, 10.0);
      const double e_hat = std::min(1.0f, sheen_directional_albedo(wo.z, r));
      for (int ch = 0; ch < 3; ++ch) {
        const Estimate e = albedo_by_bsdf_sampling(b, wo, ch, 200'000, ++seed);
        const double expected = c[ch] * e_hat + (1.0 - c[ch] * e_hat) * rho[ch];
        EXPECT_NEAR(e.mean, expected, 4.0 * e.stderr_ + c[ch] * sheen_table_error(theta) + 1e-6)
            << "r=" << r << " theta=" << theta << " channel " << ch;
      }
    }
}

// Every non-delta sample carries f = eval(wo, wi) and pdf = pdf(wo, wi), for sheens over each
// reflective base, with and without a coat over them (NEE and MIS use eval and pdf).
TEST(Sheen, SamplesCarryEvalAndPdf) {
  const Bsdf<3>::Lobe bases[] = {
      Lambertian<3>{rgb(0.3f, 0.5f, 0.7f)},
      RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.4f), ConductorFresnel<3>::schlick(S3(0.9f))},
      MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.5f, 0.6f),
      SpecularReflection<3>{S3(0.8f)},
  };
  Pcg32 rng(9, 10);
  for (const auto& base : bases)
    for (float coat : {0.0f, 0.8f}) {
      Bsdf<3> b{base};
      b.sheen = Sheen<3>::make(rgb(0.8f, 0.6f, 0.2f), 0.4f);
      b.coat = Clearcoat::make(coat, 0.3f);
      EXPECT_FALSE(b.is_specular());
      EXPECT_TRUE(b.uses_lobe_sample());
      EXPECT_TRUE(b.uses_direction_sample());
      int non_delta = 0;
      for (int i = 0; i < 2000; ++i) {
        const Vec3f wo = sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float()));
        const auto s = b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
        if (!s || s->is_specular) continue;
        ++non_delta;
        EXPECT_GT(s->wi.z * wo.z, 0.0f);
        const S3 f = b.eval(wo, s->wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c], f[c], 1e-5f * std::max(1.0f, f[c]));
        EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi), 1e-5f * std::max(1.0f, s->pdf));
      }
      EXPECT_GT(non_delta, 100);
    }
}

// Sheen::at_wo keeps E and Λ of the last wo: a BSDF asked about one wo and then another
// answers as a fresh one does, bit for bit (eval, pdf, albedo, and on the lower side).
TEST(Sheen, WhatItKeepsOfWoFollowsWo) {
  Bsdf<3> b{Lambertian<3>{rgb(0.3f, 0.5f, 0.7f)}};
  b.sheen = Sheen<3>::make(rgb(0.8f, 0.6f, 0.2f), 0.35f);
  const Bsdf<3> pristine = b;
  const Vec3f wi = direction_at(70, 150);
  for (const Vec3f& wo : {direction_at(20, 10), direction_at(85, 40), direction_at(50, 300), -direction_at(60, 90)}) {
    const Bsdf<3> fresh = pristine;
    const Vec3f w = wo.z < 0.0f ? -wi : wi;
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(b.eval(wo, w)[c], fresh.eval(wo, w)[c]) << wo.z;
      EXPECT_EQ(b.sheen.albedo(wo)[c], Bsdf<3>(pristine).sheen.albedo(wo)[c]) << wo.z;
    }
    EXPECT_EQ(b.pdf(wo, w), Bsdf<3>(pristine).pdf(wo, w)) << wo.z;
  }
}

// A black sheen is no sheen: the BSDF is the lobe's, bit for bit, and a mirror stays a delta.
TEST(Sheen, BlackSheenIsNone) {
  Bsdf<3> plain{Lambertian<3>{rgb(0.2f, 0.4f, 0.6f)}}, black = plain;
  black.sheen = Sheen<3>::make(S3(0.0f), 0.5f);
  EXPECT_FALSE(black.sheen.present());
  const Vec3f wo = direction_at(40, 10), wi = direction_at(70, 200);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(black.eval(wo, wi)[c], plain.eval(wo, wi)[c]);
  EXPECT_EQ(black.pdf(wo, wi), plain.pdf(wo, wi));
  Bsdf<3> mirror{SpecularReflection<3>{S3(1.0f)}};
  mirror.sheen = Sheen<3>::make(S3(0.0f), 0.5f);
  EXPECT_TRUE(mirror.is_specular());
  mirror.sheen = Sheen<3>::make(S3(0.5f), 0.5f);
  EXPECT_FALSE(mirror.is_specular());
}

// The lobe peaks at grazing retro-reflection (fibres seen side-on: h far from the normal),
// is symmetric in its two directions' roles apart from the normalisation, and is 0 across
// the surface.
TEST(Sheen, LobeShape) {
  const float alpha = 0.3f * 0.3f;
  EXPECT_GT(charlie_sheen_brdf(direction_at(80, 0), direction_at(80, 0), alpha),
            10.0f * charlie_sheen_brdf(direction_at(10, 0), direction_at(10, 0), alpha));
  EXPECT_GT(charlie_sheen_brdf(direction_at(80, 0), direction_at(80, 0), alpha),
            10.0f * charlie_sheen_brdf(direction_at(80, 0), direction_at(80, 180), alpha));
  EXPECT_FLOAT_EQ(charlie_sheen_brdf(direction_at(30, 0), direction_at(70, 120), alpha),
                  charlie_sheen_brdf(direction_at(70, 120), direction_at(30, 0), alpha));
  const Sheen<3> s = Sheen<3>::make(S3(1.0f), 0.3f);
  EXPECT_TRUE(s.eval(direction_at(30), -direction_at(30)).is_black());
  EXPECT_EQ(s.pdf(direction_at(30), -direction_at(30)), 0.0f);
}

}  // namespace
}  // namespace prism::bsdf
