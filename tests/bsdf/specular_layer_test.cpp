// glTF's metallic-roughness BRDF with KHR_materials_ior and KHR_materials_specular
// (bsdf/metallic_roughness.h): F0 from the IOR, the specular layer's weight, and the
// defaults that keep the core glTF model exactly.
#include <gtest/gtest.h>

#include <cmath>
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

// Weight 0 on a dielectric (metallic 0) leaves the Lambertian base alone, at every pair of
// directions; weight 1 with F0 0.04 is the core model (the defaults), bit for bit.
TEST(SpecularLayer, WeightZeroIsLambertAndTheDefaultsAreTheCoreModel) {
  const S3 c = rgb(0.6f, 0.3f, 0.1f);
  const auto none = MetallicRoughness<3>::from_roughness(c, 0.0f, 0.4f, 0.04f, 0.0f);
  const auto core = MetallicRoughness<3>::from_roughness(c, 0.3f, 0.4f);
  const auto explicit_defaults = MetallicRoughness<3>::from_roughness(c, 0.3f, 0.4f, 0.04f, 1.0f);
  Pcg32 rng(1, 2);
  for (int k = 0; k < 200; ++k) {
    const Vec3f wo = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const S3 f = none.eval(wo, wi);
    for (int i = 0; i < 3; ++i) {
      EXPECT_FLOAT_EQ(f[i], c[i] / std::numbers::pi_v<float>);
      EXPECT_EQ(core.eval(wo, wi)[i], explicit_defaults.eval(wo, wi)[i]);
    }
  }
}

// A black dielectric (c = 0, metallic 0) reflects only its specular layer; at normal
// incidence on a near-smooth lobe the albedo is s F0, F0 = ((η − 1)/(η + 1))²: for η = 2,
// 1/9. Estimated through sample() (4σ), plus 2e-3 for what the α = 0.01 lobe loses to
// shadowing and to Schlick's (1 − cos)⁵ over its width (measured: below 1e-3).
TEST(SpecularLayer, NormalIncidenceReflectsTheWeightedF0) {
  const double eta = 2.0, f0 = std::pow((eta - 1.0) / (eta + 1.0), 2.0);
  for (float weight : {1.0f, 0.5f, 0.25f}) {
    const Bsdf<3> b{MetallicRoughness<3>::from_roughness(S3(0.0f), 0.0f, 0.1f, static_cast<float>(f0), weight)};
    const Estimate e = monte_carlo(100'000, 7, [&](Pcg32& rng) {
      const auto s = b.sample(direction_at(0.0), rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
      return s ? double(s->f[0]) * std::abs(s->wi.z) / s->pdf : 0.0;
    });
    EXPECT_NEAR(e.mean, weight * f0, 4.0 * e.stderr_ + 2e-3) << weight;
  }
}

// Weight 0 gives the specular lobe no energy, so sampling never picks it (a lobe with
// f ≡ 0 gets probability 0) and a white base is Lambert's: every sample weighs exactly 1.
TEST(SpecularLayer, WhiteFurnaceWithWeightZeroIsOne) {
  const Bsdf<3> b{MetallicRoughness<3>::from_roughness(S3(1.0f), 0.0f, 0.5f, 0.04f, 0.0f)};
  for (double theta : {0.0, 60.0, 85.0}) {
    const Estimate e = monte_carlo(50'000, 8, [&](Pcg32& rng) {
      const auto s = b.sample(direction_at(theta), rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
      return s ? double(s->f[0]) * std::abs(s->wi.z) / s->pdf : 0.0;
    });
    EXPECT_NEAR(e.mean, 1.0, 1e-5) << theta;  // every sample weighs exactly 1
  }
}

// A tinted F0 (KHR_materials_specular's specularColorFactor) colours the specular lobe per
// channel, F_c = F0_c + (1 − F0_c)(1 − wi·h)⁵, and dims the diffuse base by
// 1 − s F(max F0) in every channel (the extension's fresnel_mix); a grey one is the
// scalar constructor's BSDF bit for bit.
TEST(SpecularLayer, TintedF0ColoursTheLobeAndDimsTheBaseByItsLargestComponent) {
  const S3 c = rgb(0.6f, 0.3f, 0.1f), f0 = rgb(0.3f, 0.05f, 0.0f);
  const float weight = 0.7f, metallic = 0.2f;
  const auto tinted = MetallicRoughness<3>::from_roughness(c, metallic, 0.4f, f0, 0.3f, weight);
  const auto grey_scalar = MetallicRoughness<3>::from_roughness(c, metallic, 0.4f, 0.12f, weight);
  const auto grey_spectrum = MetallicRoughness<3>::from_roughness(c, metallic, 0.4f, S3(0.12f), 0.12f, weight);
  const auto lobe_only = MetallicRoughness<3>::from_roughness(S3(0.0f), 0.0f, 0.4f, 1.0f, 1.0f);  // F ≡ 1
  Pcg32 rng(3, 4);
  for (int k = 0; k < 200; ++k) {
    const Vec3f wo = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const Vec3f wi = sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
    const float i_h = dot(wi, normalize(wo + wi));
    const float lobe = lobe_only.eval(wo, wi)[0];  // D G2 / (4 cos θo cos θi)
    const float diffuse = (1.0f - metallic) * (1.0f - weight * fresnel_schlick(0.3f, i_h)) / std::numbers::pi_v<float>;
    const S3 f = tinted.eval(wo, wi);
    for (int i = 0; i < 3; ++i) {
      const float specular = metallic * fresnel_schlick(c[i], i_h) + (1.0f - metallic) * weight * fresnel_schlick(f0[i], i_h);
      // float rounding of the two sums (a few ulps of values ≤ 1)
      EXPECT_NEAR(f[i], c[i] * diffuse + specular * lobe, 1e-5f * (1.0f + f[i])) << i;
      EXPECT_EQ(grey_scalar.eval(wo, wi)[i], grey_spectrum.eval(wo, wi)[i]);
    }
    EXPECT_EQ(grey_scalar.pdf(wo, wi), grey_spectrum.pdf(wo, wi));
  }
}

}  // namespace
}  // namespace prism::bsdf
