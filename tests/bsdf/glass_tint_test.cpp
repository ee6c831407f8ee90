// Glass tinted by its base colour (glTF KHR_materials_transmission's BTDF × base colour,
// MTL Ks, JSON base_color): the tint multiplies transmitted light, per channel, and leaves
// reflection alone, in every path of the smooth, rough and thin dielectrics.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/bsdf/dielectric.h"
#include "prism/bsdf/thin_dielectric.h"
#include "prism/core/pcg32.h"

namespace prism::bsdf {
namespace {

using S3 = color::SampledSpectrum<3>;

const S3 kTint = [] {
  S3 t;
  t[0] = 1.0f;
  t[1] = 0.5f;
  t[2] = 0.25f;
  return t;
}();

Vec3f unit(float x, float y, float z) { return normalize(Vec3f(x, y, z)); }

TEST(GlassTint, SmoothDielectricTintsTransmissionOnly) {
  const Dielectric<3> clear{S3(1.5f)};
  const Dielectric<3> tinted{S3(1.5f), clear.distribution, kTint};
  const Vec3f wo = unit(0.3f, 0.1f, 0.9f);
  for (const float u_lobe : {0.01f, 0.99f}) {  // reflection (F ≈ 0.04), then transmission
    const auto a = clear.sample(wo, u_lobe, Vec2f(0.5f, 0.5f));
    const auto b = tinted.sample(wo, u_lobe, Vec2f(0.5f, 0.5f));
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->is_transmission, u_lobe > 0.5f);
    EXPECT_EQ(a->wi, b->wi);
    EXPECT_EQ(a->pdf, b->pdf);  // the lobe choice does not depend on the tint
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(b->f[c], a->f[c] * (a->is_transmission ? kTint[c] : 1.0f)) << c;
  }
}

TEST(GlassTint, RoughDielectricTintsTransmissionInEvalAndSample) {
  const auto rough = MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f);
  const Dielectric<3> clear{S3(1.5f), rough};
  const Dielectric<3> tinted{S3(1.5f), rough, kTint};
  const Vec3f wo = unit(0.2f, -0.3f, 0.8f);
  // eval: below the surface the tint, above it none; pdf unchanged.
  for (const Vec3f wi : {unit(-0.1f, 0.2f, -0.9f), unit(-0.3f, 0.4f, 0.8f)}) {
    const S3 a = clear.eval(wo, wi), b = tinted.eval(wo, wi);
    ASSERT_GT(a[0], 0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(b[c], a[c] * (wi.z < 0.0f ? kTint[c] : 1.0f)) << c;
    EXPECT_EQ(clear.pdf(wo, wi), tinted.pdf(wo, wi));
  }
  // sample: both lobes, from above and from inside.
  Pcg32 rng(7, 1);
  int transmitted = 0, reflected = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3f from = i % 2 ? wo : -wo;
    const float u_lobe = rng.next_float();
    const Vec2f u(rng.next_float(), rng.next_float());
    const auto a = clear.sample(from, u_lobe, u), b = tinted.sample(from, u_lobe, u);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a) continue;
    (a->is_transmission ? transmitted : reflected) += 1;
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(b->f[c], a->f[c] * (a->is_transmission ? kTint[c] : 1.0f));
  }
  EXPECT_GT(transmitted, 500);
  EXPECT_GT(reflected, 20);
}

TEST(GlassTint, ThinDielectricTintsTheStraightThroughPath) {
  const ThinDielectric<3> clear{S3(1.5f)};
  const ThinDielectric<3> tinted{S3(1.5f), kTint};
  const Vec3f wo = unit(0.0f, 0.0f, 1.0f);
  const auto through = tinted.sample(wo, 0.9f, Vec2f(0.0f, 0.0f));
  const auto back = tinted.sample(wo, 0.01f, Vec2f(0.0f, 0.0f));
  ASSERT_TRUE(through && back);
  ASSERT_TRUE(through->is_transmission);
  for (int c = 0; c < 3; ++c) {
    // f |cos| / pdf = T' tint / (1 − R') = tint: the path's weight is the tint itself.
    EXPECT_NEAR(through->f[c] * std::abs(through->wi.z) / through->pdf, kTint[c], 1e-6f) << c;
    EXPECT_FLOAT_EQ(back->f[c], clear.sample(wo, 0.01f, Vec2f(0.0f, 0.0f))->f[c]);  // reflection untinted
  }
}

}  // namespace
}  // namespace prism::bsdf
