// Energy and consistency checks: pdfs integrate to 1 (or to 1 − the failure rate), white
// furnace, reciprocity. Statistical bounds are 4 standard errors of the estimate (two-
// sided false-alarm rate 6e-5 per check), the standard error estimated from the samples.
#include "prism/bsdf/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>
#include <variant>

#include "bsdf/bsdf_test_helpers.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"

namespace prism::bsdf {
namespace {

using S3 = color::SampledSpectrum<3>;
using test_helpers::direction_at;
using test_helpers::Estimate;
using test_helpers::monte_carlo;

// ∫ pdf(wo, wi) dωi by uniform-sphere sampling equals the probability that sample()
// succeeds (both estimated; their difference is compared with 4 combined standard errors).
TEST(BsdfEnergy, PdfIntegratesToSamplingSuccessRate) {
  const Bsdf<3> bsdfs[] = {
      {Lambertian<3>{S3(0.5f)}},
      {RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f), ConductorFresnel<3>::schlick(S3(1))}},
      {RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::beckmann, 0.5f), ConductorFresnel<3>::schlick(S3(1))}},
      {MetallicRoughness<3>::from_roughness(S3(0.5f), 0.3f, 0.6f)},
      {Dielectric<3>{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f)}},
      // Anisotropic (render/anisotropy.h): α along x and y differ.
      {RoughConductor<3>{{MicrofacetType::ggx, 0.6f, 0.08f}, ConductorFresnel<3>::schlick(S3(1))}},
      {Dielectric<3>{S3(1.5f), {MicrofacetType::ggx, 0.1f, 0.5f}}},
  };
  constexpr long kN = 400'000;
  for (const auto& b : bsdfs)
    for (const Vec3f& wo : {direction_at(20), direction_at(70), -direction_at(50)}) {
      const Estimate integral = monte_carlo(kN, 3, [&](Pcg32& rng) {
        const Vec3f wi = sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float()));
        return double(b.pdf(wo, wi)) / uniform_sphere_pdf();
      });
      const Estimate success = monte_carlo(kN, 4, [&](Pcg32& rng) {
        return b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float())) ? 1.0 : 0.0;
      });
      const double bound = 4.0 * std::hypot(integral.stderr_, success.stderr_);
      EXPECT_NEAR(integral.mean, success.mean, bound) << b.lobe.index() << " wo.z=" << wo.z;
      EXPECT_LE(success.mean, 1.0);
    }
}

TEST(BsdfEnergy, ReciprocityOfReflection) {
  const Bsdf<3> bsdfs[] = {
      {Lambertian<3>{S3(0.5f)}},
      {RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f), ConductorFresnel<3>::complex_ior(S3(0.29f), S3(2.86f))}},
      {MetallicRoughness<3>::from_roughness(S3(0.5f), 0.3f, 0.6f)},
      {Dielectric<3>{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f)}},
      {RoughConductor<3>{{MicrofacetType::ggx, 0.6f, 0.08f}, ConductorFresnel<3>::complex_ior(S3(0.29f), S3(2.86f))}},
      {RoughConductor<3>{{MicrofacetType::beckmann, 0.1f, 0.4f}, ConductorFresnel<3>::schlick(S3(0.9f))}},
  };
  Pcg32 rng(8, 9);
  for (const auto& b : bsdfs)
    for (int i = 0; i < 1000; ++i) {
      Vec3f wo = sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float()));
      Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
      if (wo.z < 0) wi.z = -wi.z;
      const float a = b.eval(wo, wi)[0], c = b.eval(wi, wo)[0];
      EXPECT_NEAR(a, c, 1e-4f * std::max(1.0f, a)) << b.lobe.index();  // float rounding only
    }
  // Refraction: the radiance BTDF obeys f(wo, wi)/η_o² = f(wi, wo)/η_i² (dielectric.h).
  const Dielectric<3> d{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.4f)};
  for (int i = 0; i < 1000; ++i) {
    const Vec3f wo = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    wi.z = -wi.z;  // wo outside (η 1), wi inside (η 1.5)
    const float a = d.eval(wo, wi)[0] / 1.0f, c = d.eval(wi, wo)[0] / (1.5f * 1.5f);
    EXPECT_NEAR(a, c, 1e-4f * std::max(1.0f, a));
  }
}

// White furnace: albedo ∫ f cos dωi estimated with cosine-hemisphere sampling (independent
// of the BSDF's own sampler) and with sample() (weight f cos/pdf).
TEST(BsdfEnergy, LambertWhiteFurnaceIsOne) {
  const Lambertian<3> l{S3(1.0f)};
  const Estimate e = monte_carlo(200'000, 5, [&](Pcg32& rng) {
    const Vec3f wi = sample_uniform_sphere(Vec2f(rng.next_float(), rng.next_float()));
    return double(l.eval(direction_at(30), wi)[0]) * std::abs(wi.z) / uniform_sphere_pdf();
  });
  EXPECT_NEAR(e.mean, 1.0, 4.0 * e.stderr_);
  RecordProperty("lambert_albedo", std::to_string(e.mean));
}

double conductor_albedo(float alpha, const Vec3f& wo, bool use_bsdf_sampling, double* err) {
  const RoughConductor<3> c{MicrofacetDistribution::isotropic(MicrofacetType::ggx, alpha), ConductorFresnel<3>::schlick(S3(1))};
  const Estimate e = monte_carlo(200'000, 6, [&](Pcg32& rng) {
    if (use_bsdf_sampling) {
      const auto s = c.sample(wo, 0.5f, Vec2f(rng.next_float(), rng.next_float()));
      return s ? double(s->f[0]) * s->wi.z / s->pdf : 0.0;
    }
    const Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    return double(c.eval(wo, wi)[0]) * wi.z / cosine_hemisphere_pdf(wi.z);
  });
  *err = e.stderr_;
  return e.mean;
}

// GGX conductor with F = 1: single scattering loses energy growing with α (Heitz et al.
// 2016), never gains, and is lossless as α → 0. Measured at 45°: 0.99986, 0.99593, 0.84567,
// 0.47931 for α = 0.01, 0.05, 0.3, 0.8; an independent 400×800 midpoint quadrature of
// ∫ f cos dωi gives 0.48025 at α = 0.8.
TEST(BsdfEnergy, GgxConductorFurnaceLosesOnlySingleScatteringEnergy) {
  const Vec3f wo = direction_at(45);
  double prev = 2.0, prev_err = 0.0;
  for (float alpha : {0.01f, 0.05f, 0.3f, 0.8f}) {
    double err_is = 0, err_cos = 0;
    const double e_is = conductor_albedo(alpha, wo, true, &err_is);
    EXPECT_LE(e_is, 1.0 + 4 * err_is) << alpha;
    EXPECT_LT(e_is, prev + 4 * std::hypot(err_is, prev_err)) << alpha;
    if (alpha >= 0.3f) {  // the cosine-sampled estimate is too noisy for sharp lobes
      const double e_cos = conductor_albedo(alpha, wo, false, &err_cos);
      EXPECT_NEAR(e_is, e_cos, 4 * std::hypot(err_is, err_cos)) << alpha;
    }
    if (alpha == 0.01f) {
      EXPECT_NEAR(e_is, 1.0, 1e-3);  // loss O(α²) ≈ 1e-4 plus noise
    }
    RecordProperty("ggx_albedo_" + std::to_string(alpha), std::to_string(e_is));
    std::printf("GGX F=1 albedo at 45°, α=%.2f: %.5f ± %.5f\n", alpha, e_is, err_is);
    prev = e_is;
    prev_err = err_is;
  }
}

// Smooth dielectric: every sample's weight f cos/pdf is exactly 1 in importance mode
// (R/R or T/T: R + T = 1), and 1/η² for radiance crossing into the denser side.
TEST(BsdfEnergy, SmoothDielectricReflectancePlusTransmittanceIsOne) {
  const Dielectric<3> d{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.0f)};
  Pcg32 rng(1, 2);
  for (const Vec3f& wo : {direction_at(0), direction_at(60), -direction_at(20)}) {
    for (int i = 0; i < 200; ++i) {
      const auto s = d.sample(wo, rng.next_float(), Vec2f(0.5f, 0.5f), TransportMode::importance);
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 1.0f, 1e-5f);
      const auto r = d.sample(wo, rng.next_float(), Vec2f(0.5f, 0.5f));
      const float expected = r->is_transmission ? 1.0f / (r->eta * r->eta) : 1.0f;
      EXPECT_NEAR(r->f[0] * std::abs(r->wi.z) / r->pdf, expected, 1e-5f);
    }
  }
}

// Rough dielectric, importance mode from outside: R + T ≤ 1 (single scattering), close to
// 1 when smooth-ish.
TEST(BsdfEnergy, RoughDielectricFurnace) {
  for (float alpha : {0.05f, 0.3f, 0.8f}) {
    const Dielectric<3> d{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, alpha)};
    const Vec3f wo = direction_at(30);
    const Estimate e = monte_carlo(100'000, 7, [&](Pcg32& rng) {
      const auto s = d.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()), TransportMode::importance);
      return s ? double(s->f[0]) * std::abs(s->wi.z) / s->pdf : 0.0;
    });
    std::printf("rough dielectric R+T at 30°, α=%.2f: %.5f ± %.5f\n", alpha, e.mean, e.stderr_);
    EXPECT_LE(e.mean, 1.0 + 4 * e.stderr_);
    if (alpha == 0.05f) {
      EXPECT_GT(e.mean, 0.99);
    }
  }
}

}  // namespace
}  // namespace prism::bsdf

namespace prism::bsdf {
namespace {

// The integrator skips drawing the numbers a BSDF does not read (uses_lobe_sample,
// uses_direction_sample): a lobe that says it ignores u_lobe (or u) must sample the same
// direction and weight whatever that number is, and every lobe of the variant is listed
// here, so a lobe added later without updating those predicates fails this test.
TEST(BsdfNumberUse, LobesIgnoreExactlyTheNumbersTheySayTheyIgnore) {
  const Bsdf<3> bsdfs[] = {
      {Lambertian<3>{S3(0.5f)}},
      {SpecularReflection<3>{S3(0.9f)}},
      {RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f), ConductorFresnel<3>::schlick(S3(1))}},
      {Dielectric<3>{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f)}},
      {MetallicRoughness<3>::from_roughness(S3(0.5f), 0.3f, 0.6f)},
      {ThinDielectric<3>{S3(1.5f)}},
  };
  static_assert(std::variant_size_v<Bsdf<3>::Lobe> == std::size(bsdfs), "list every lobe of the variant here");
  const auto same = [](const std::optional<BsdfSample<3>>& a, const std::optional<BsdfSample<3>>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return a->wi.x == b->wi.x && a->wi.y == b->wi.y && a->wi.z == b->wi.z && a->pdf == b->pdf && a->f[0] == b->f[0];
  };
  for (std::size_t i = 0; i < std::size(bsdfs); ++i) {
    const Bsdf<3>& b = bsdfs[i];
    EXPECT_EQ(b.lobe.index(), i);
    bool lobe_matters = false, direction_matters = false;
    for (const Vec3f& wo : {normalize(Vec3f(0.3f, 0.1f, 0.9f)), normalize(Vec3f(-0.6f, 0.2f, 0.3f))})
      for (float u_lobe : {0.02f, 0.5f, 0.98f})
        for (float u : {0.1f, 0.7f}) {
          const auto reference = b.sample(wo, u_lobe, Vec2f(u, 0.4f));
          if (!same(reference, b.sample(wo, 1.0f - u_lobe, Vec2f(u, 0.4f)))) lobe_matters = true;
          if (!same(reference, b.sample(wo, u_lobe, Vec2f(1.0f - u, 0.8f)))) direction_matters = true;
        }
    if (lobe_matters) {
      EXPECT_TRUE(b.uses_lobe_sample()) << "lobe " << i << " reads u_lobe but says it does not";
    }
    if (direction_matters) {
      EXPECT_TRUE(b.uses_direction_sample()) << "lobe " << i << " reads u but says it does not";
    }
  }
}

}  // namespace
}  // namespace prism::bsdf
