// Clear coat (bsdf/clearcoat.h): the tabulated albedo against Monte Carlo, white furnaces
// (exactly 1 over a white Lambertian base, never above 1 over anything), the smooth coat's
// lobe choice and weights, and sample() against pdf() and eval() on coated lobes.
// Statistical bounds are 4 standard errors (two-sided false-alarm rate 6e-5 per check).
#include "prism/bsdf/clearcoat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "bsdf/bsdf_test_helpers.h"
#include "prism/bsdf/bsdf.h"
#include "prism/bsdf/fresnel.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"

namespace prism::bsdf {
namespace {

using S3 = color::SampledSpectrum<3>;
using test_helpers::direction_at;
using test_helpers::Estimate;
using test_helpers::monte_carlo;
using test_helpers::rgb;

// The albedo of a unit-weight coat from wo, ∫ f_coat cos θi dωi, estimated independently of
// the table (VNDF quadrature) and of the coat's own sampler: microfacet normals drawn from
// D(h) cos θh (classic NDF sampling), weighted by Clearcoat::eval.
Estimate coat_albedo_by_ndf_sampling(float r, const Vec3f& wo, long n, unsigned long long seed) {
  const Clearcoat c = Clearcoat::make(1.0f, r);
  return monte_carlo(n, seed, [&](Pcg32& rng) {
    const Vec3f h = c.distribution.sample_ndf(Vec2f(rng.next_float(), rng.next_float()));
    const Vec3f wi = reflect(wo, h);
    const double pdf = double(c.distribution.pdf_ndf(h)) * reflection_jacobian(wo, h);
    return wi.z > 0.0f && pdf > 0.0 ? double(c.eval(wo, wi)) * wi.z / pdf : 0.0;
  });
}

// Off the table's nodes (r between nodes, cos θ between nodes), bilinear interpolation of
// the 32² midpoint-rule table must agree with an independent estimate. Measured: at most
// 0.0006 apart below 80° and 0.0014 at 80° (E curves most at grazing angles, where one
// 1/31 step in cos θ moves it by up to 0.05), against estimates with σ ≤ 0.0003. The bounds
// are 4σ plus about 3 × those: kTableError, kTableErrorGrazing (also used by the furnaces).
constexpr double kTableError = 0.002, kTableErrorGrazing = 0.004;
double table_error(float r, double theta_deg) {
  return r == 0.0f ? 0.0 : (theta_deg >= 80.0 ? kTableErrorGrazing : kTableError);
}

TEST(Clearcoat, TabulatedAlbedoMatchesIndependentEstimate) {
  const float roughnesses[] = {0.05f, 0.21f, 0.5f, 0.83f, 1.0f};
  const double thetas[] = {0.0, 33.3, 61.0, 80.0};
  unsigned long long seed = 1;
  for (float r : roughnesses)
    for (double theta : thetas) {
      const Vec3f wo = direction_at(theta, 25.0);
      const Estimate e = coat_albedo_by_ndf_sampling(r, wo, 200'000, ++seed);
      const double table = coat_directional_albedo(wo.z, r);
      EXPECT_NEAR(table, e.mean, 4.0 * e.stderr_ + table_error(r, theta)) << "r=" << r << " theta=" << theta;
      std::printf("coat albedo r=%.2f theta=%4.1f: table %.5f, estimate %.5f ± %.5f\n", r, theta, table, e.mean,
                  e.stderr_);
    }
  // r = 0 and the smooth coat are the Fresnel reflectance itself.
  for (double theta : {0.0, 45.0, 75.0}) {
    const Vec3f wo = direction_at(theta);
    EXPECT_NEAR(coat_directional_albedo(wo.z, 0.0f), fresnel_dielectric(wo.z, 1.5f), 1e-3f);
    EXPECT_FLOAT_EQ(Clearcoat::make(0.7f, 0.0f).albedo(wo), 0.7f * fresnel_dielectric(wo.z, 1.5f));
  }
  // Published value: a smooth η = 1.5 interface reflects 4 % at normal incidence.
  EXPECT_NEAR(Clearcoat::make(1.0f, 0.0f).albedo(Vec3f(0, 0, 1)), 0.04f, 1e-6f);
}

// The coated BSDF's albedo at wo, through its own sampler (f cos/pdf per sample, summing the
// smooth coat's delta samples too).
Estimate albedo_by_bsdf_sampling(const Bsdf<3>& b, const Vec3f& wo, long n, unsigned long long seed) {
  return monte_carlo(n, seed, [&](Pcg32& rng) {
    const auto s = b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    return s ? double(s->f[0]) * std::abs(s->wi.z) / s->pdf : 0.0;
  });
}

// A white Lambertian base under a coat of weight 1: albedo = A_c + (1 − A_c)·1 = 1 at every
// angle and roughness (the point of weighting by the albedo). The bound is 4σ plus the
// table's error (the test above).
TEST(Clearcoat, WhiteFurnaceOverWhiteLambertIsOne) {
  unsigned long long seed = 100;
  for (float r : {0.0f, 0.1f, 0.4f, 0.9f})
    for (double theta : {0.0, 45.0, 80.0}) {
      Bsdf<3> b{Lambertian<3>{S3(1.0f)}};
      b.coat = Clearcoat::make(1.0f, r);
      const Vec3f wo = direction_at(theta, 70.0);
      const Estimate e = albedo_by_bsdf_sampling(b, wo, 200'000, ++seed);
      const double slack = table_error(r, theta);
      EXPECT_NEAR(e.mean, 1.0, 4.0 * e.stderr_ + slack + 1e-6) << "r=" << r << " theta=" << theta;
    }
}

// Over any base the coat reflects A_c = c E and passes 1 − A_c on: the coated albedo is
// A_c + (1 − A_c) A_base, with A_base the base's own albedo (estimated alone, with other
// numbers). So a base that conserves energy stays below 1 under a coat. (glTF's
// metallic-roughness BRDF itself exceeds 1 at grazing angles, 1.04 at 85° for a white
// dielectric base: its diffuse weight 1 − F(wi·h) is not the specular lobe's albedo.)
// Bound: 4 combined σ plus the table's error (c = 1).
TEST(Clearcoat, BaseReceivesWhatTheCoatDoesNotReflect) {
  const Bsdf<3>::Lobe bases[] = {
      RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.2f), ConductorFresnel<3>::schlick(S3(1))},
      MetallicRoughness<3>::from_roughness(S3(1.0f), 0.0f, 0.5f),
      MetallicRoughness<3>::from_roughness(S3(1.0f), 1.0f, 0.3f),
      SpecularReflection<3>{S3(1.0f)},
  };
  unsigned long long seed = 200;
  for (const auto& base : bases)
    for (float r : {0.0f, 0.3f, 1.0f})
      for (double theta : {0.0, 60.0, 85.0}) {
        const Bsdf<3> plain{base};
        Bsdf<3> coated{base};
        coated.coat = Clearcoat::make(1.0f, r);
        const Vec3f wo = direction_at(theta, 10.0);
        const Estimate e_base = albedo_by_bsdf_sampling(plain, wo, 100'000, ++seed);
        const Estimate e = albedo_by_bsdf_sampling(coated, wo, 100'000, ++seed);
        const double a_c = coated.coat.albedo(wo);
        const double expected = a_c + (1.0 - a_c) * e_base.mean;
        const double slack = table_error(r, theta);
        EXPECT_NEAR(e.mean, expected, 4.0 * std::hypot(e.stderr_, e_base.stderr_) + slack + 1e-6)
            << base.index() << " r=" << r << " theta=" << theta;
        if (e_base.mean <= 1.0) {
          EXPECT_LE(e.mean, 1.0 + 4.0 * e.stderr_ + slack + 1e-6);
        }
      }
  // A smooth coat over a black base reflects exactly c F(cos θo) in expectation.
  Bsdf<3> black{Lambertian<3>{S3(0.0f)}};
  black.coat = Clearcoat::make(0.6f, 0.0f);
  for (double theta : {0.0, 50.0, 85.0}) {
    const Vec3f wo = direction_at(theta);
    const Estimate e = albedo_by_bsdf_sampling(black, wo, 100'000, ++seed);
    EXPECT_NEAR(e.mean, 0.6 * fresnel_dielectric(wo.z, 1.5f), 4.0 * e.stderr_ + 1e-6) << theta;
  }
}

// Smooth coat over a diffuse base: the coat is chosen with probability p_c (binomial, 4σ),
// its samples are the mirror direction with weight A_c / p_c, and the others are the base's
// with weight (1 − A_c) R / (1 − p_c) (Lambert: f cos/pdf = R).
TEST(Clearcoat, SmoothCoatChoosesTheMirrorWithItsProbability) {
  Bsdf<3> b{Lambertian<3>{S3(0.5f)}};
  b.coat = Clearcoat::make(0.8f, 0.0f);
  EXPECT_FALSE(b.is_specular());
  EXPECT_TRUE(b.uses_lobe_sample());
  for (const Vec3f& wo : {direction_at(10, 30), direction_at(70, 30), -direction_at(40, 200)}) {
    const float p_c = b.coat_probability(wo, b.coat.albedo(wo));
    const float a_c = 0.8f * fresnel_dielectric(std::abs(wo.z), 1.5f);
    Pcg32 rng(5, 6);
    constexpr int kN = 100'000;
    int specular = 0;
    for (int i = 0; i < kN; ++i) {
      const auto s = b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
      ASSERT_TRUE(s);
      const float weight = s->f[0] * std::abs(s->wi.z) / s->pdf;
      if (s->is_specular) {
        ++specular;
        EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
        EXPECT_NEAR(s->wi.z, wo.z, 1e-6f);
        EXPECT_NEAR(weight, a_c / p_c, 1e-5f * a_c / p_c);
      } else {
        EXPECT_GT(s->wi.z * wo.z, 0.0f);
        EXPECT_NEAR(weight, (1.0f - a_c) * 0.5f / (1.0f - p_c), 1e-4f);
        EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi), 1e-5f * s->pdf);
      }
    }
    const double sigma = std::sqrt(p_c * (1.0 - p_c) / kN);
    EXPECT_NEAR(double(specular) / kN, p_c, 4.0 * sigma) << wo.z;
  }
}

// Every non-delta sample carries f = eval(wo, wi) and pdf = pdf(wo, wi), for coats over each
// reflective base (eval and pdf are what NEE and MIS use, so they must agree with sample).
TEST(Clearcoat, SamplesCarryEvalAndPdf) {
  const Bsdf<3>::Lobe bases[] = {
      Lambertian<3>{rgb(0.3f, 0.5f, 0.7f)},
      RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.4f), ConductorFresnel<3>::schlick(S3(0.9f))},
      MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.5f, 0.6f),
  };
  Pcg32 rng(9, 10);
  for (const auto& base : bases)
    for (float r : {0.0f, 0.25f, 0.8f}) {
      Bsdf<3> b{base};
      b.coat = Clearcoat::make(0.9f, r);
      for (int i = 0; i < 2000; ++i) {
        const Vec3f wo = sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float()));
        const auto s = b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
        if (!s || s->is_specular) continue;
        const S3 f = b.eval(wo, s->wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c], f[c], 1e-5f * std::max(1.0f, f[c]));
        EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi), 1e-5f * std::max(1.0f, s->pdf));
      }
    }
}

// The coat is colourless and its base weight 1 − A_c: over a coloured base, a coat of
// weight 0 changes nothing, and the coated eval is the base's scaled plus a grey term.
TEST(Clearcoat, CoatAddsAGreyLayerAndDimsTheBase) {
  const Lambertian<3> base{rgb(0.2f, 0.4f, 0.6f)};
  Bsdf<3> plain{base}, zero{base}, coated{base};
  zero.coat = Clearcoat::make(0.0f, 0.3f);
  coated.coat = Clearcoat::make(1.0f, 0.3f);
  const Vec3f wo = direction_at(40, 10), wi = direction_at(40, 190);  // the mirror direction
  for (int c = 0; c < 3; ++c) EXPECT_EQ(zero.eval(wo, wi)[c], plain.eval(wo, wi)[c]);
  EXPECT_EQ(zero.pdf(wo, wi), plain.pdf(wo, wi));
  const S3 f = coated.eval(wo, wi);
  const float grey = coated.coat.eval(wo, wi);
  EXPECT_GT(grey, 0.0f);
  const float w = 1.0f - coat_directional_albedo(wo.z, 0.3f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], w * base.reflectance[c] / std::numbers::pi_v<float> + grey, 1e-6f);
}

// A coat with its own normal (clearcoatNormalTexture): `tilt_deg` about the y axis.
Frame tilted_frame(double tilt_deg) {
  const float t = static_cast<float>(tilt_deg * std::numbers::pi / 180.0);
  return *Frame::from_normal_and_tangent(Vec3f(std::sin(t), 0.0f, std::cos(t)), Vec3f(1, 0, 0));
}

// The untilted frame changes nothing; a tilted smooth coat mirrors about its own normal;
// a tilted rough coat's eval is c f_coat in its frame times the ratio of the cosines; its
// samples carry eval and pdf and never leave below the base's surface.
TEST(Clearcoat, OwnNormalReflectsAboutIt) {
  Pcg32 rng(11, 12);
  Clearcoat plain = Clearcoat::make(0.9f, 0.4f);
  Clearcoat identity = plain;
  const Frame identity_frame{Vec3f(1, 0, 0), Vec3f(0, 1, 0), Vec3f(0, 0, 1)};
  identity.frame = &identity_frame;
  for (int i = 0; i < 200; ++i) {
    const Vec3f wo = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    EXPECT_FLOAT_EQ(identity.eval(wo, wi), plain.eval(wo, wi));
    EXPECT_FLOAT_EQ(identity.pdf(wo, wi), plain.pdf(wo, wi));
    EXPECT_FLOAT_EQ(identity.albedo(wo), plain.albedo(wo));
  }
  // Smooth, tilted 10°: seen from straight above, the mirror direction is 20° off.
  Clearcoat mirror = Clearcoat::make(1.0f, 0.0f);
  const Frame ten_degrees = tilted_frame(10.0);
  mirror.frame = &ten_degrees;
  const auto wi = mirror.sample_direction(Vec3f(0, 0, 1), Vec2f(0.5f, 0.5f));
  ASSERT_TRUE(wi);
  const float twenty = static_cast<float>(20.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(wi->x, std::sin(twenty), 1e-6f);
  EXPECT_NEAR(wi->z, std::cos(twenty), 1e-6f);
  // Its albedo is the Fresnel reflectance at the angle to its own normal.
  EXPECT_NEAR(mirror.albedo(Vec3f(0, 0, 1)), fresnel_dielectric(std::cos(twenty / 2), Clearcoat::kIor), 1e-6f);
  // Rough and tilted 25°: eval in the coat's frame with its cosine.
  Clearcoat rough = Clearcoat::make(0.9f, 0.4f);
  const Frame twenty_five_degrees = tilted_frame(25.0);
  rough.frame = &twenty_five_degrees;
  long below = 0, drawn = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3f wo = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const Vec3f o = rough.frame->to_local(wo);
    const Vec3f v = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    if (o.z > 0.0f) {
      const Vec3f i = rough.frame->to_local(v);
      EXPECT_NEAR(rough.eval(wo, v), plain.eval(o, i) * std::abs(i.z) / v.z, 1e-5f);
    }
    const auto s = rough.sample_direction(wo, Vec2f(rng.next_float(), rng.next_float()));
    ++drawn;
    if (!s) {
      ++below;
      continue;
    }
    EXPECT_GT(s->z, 0.0f);
    EXPECT_GT(rough.pdf(wo, *s), 0.0f);
  }
  EXPECT_GT(below, 0);  // a tilted coat does send some reflections below the base: dropped
  EXPECT_LT(below, drawn / 4);
}

}  // namespace
}  // namespace prism::bsdf
