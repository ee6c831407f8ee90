// An index-matched dielectric (η = 1) is invisible however rough it is: every sample passes
// straight through with weight 1 (pbrt-v4's DielectricBxDF treats η = 1 as smooth). The
// rough model alone returned no sample there (its transmission half-vector vanishes).
#include <gtest/gtest.h>

#include "prism/bsdf/dielectric.h"
#include "prism/core/pcg32.h"

namespace prism::bsdf {
namespace {

TEST(IndexMatchedDielectric, RoughGlassOfIorOnePassesLightUnbent) {
  using S3 = color::SampledSpectrum<3>;
  for (const float roughness : {0.0f, 0.3f, 1.0f}) {
    const Dielectric<3> glass{S3(1.0f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, roughness * roughness)};
    EXPECT_TRUE(glass.is_specular()) << roughness;
    Pcg32 rng(7, 3);
    for (int i = 0; i < 100; ++i) {
      const Vec3f wo = normalize(Vec3f(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() + 0.05f));
      const auto s = glass.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
      ASSERT_TRUE(s) << roughness;
      EXPECT_TRUE(s->is_transmission);
      EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
      EXPECT_NEAR(s->wi.y, -wo.y, 1e-6f);
      EXPECT_NEAR(s->wi.z, -wo.z, 1e-6f);
      // f cos / pdf: the path's weight is unchanged (up to float rounding of 1/cos · cos).
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c] * std::abs(s->wi.z) / s->pdf, 1.0f, 1e-6f) << c;
    }
  }
  // Any other η keeps the rough model.
  EXPECT_FALSE((Dielectric<3>{S3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.09f)}.is_specular()));
}

}  // namespace
}  // namespace prism::bsdf
