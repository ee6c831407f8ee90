// PlainDiffuseBsdf against the Bsdf it stands in for: a Bsdf holding only a Lambertian lobe.
// The integrator shades plain diffuse hits with the former and every other hit with the
// latter, and promises the same image either way, so every answer must be the same bits.
#include "prism/bsdf/plain_diffuse_bsdf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "prism/bsdf/bsdf.h"
#include "prism/core/pcg32.h"

namespace prism::bsdf {
namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

template <int N>
bool same_bits(const color::SampledSpectrum<N>& a, const color::SampledSpectrum<N>& b) {
  for (std::size_t c = 0; c < N; ++c)
    if (!same_bits(a[c], b[c])) return false;
  return true;
}

// A direction on either side of the surface, now and then in the plane (z = 0) or on the
// normal, where the lobe's edge cases are.
Vec3f any_direction(Pcg32& rng) {
  const float u = rng.next_float();
  if (u < 0.05f) return Vec3f(0.6f, 0.8f, 0.0f);
  if (u < 0.10f) return Vec3f(0.0f, 0.0f, rng.next_float() < 0.5f ? 1.0f : -1.0f);
  const float z = 2.0f * rng.next_float() - 1.0f, phi = 6.2831853f * rng.next_float();
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return Vec3f(r * std::cos(phi), r * std::sin(phi), z);
}

template <int N>
void expect_same_answers() {
  Pcg32 rng(7, 11);
  for (int trial = 0; trial < 20000; ++trial) {
    color::SampledSpectrum<N> reflectance;
    for (int c = 0; c < N; ++c) reflectance[static_cast<std::size_t>(c)] = rng.next_float();
    const Bsdf<N> general{Lambertian<N>{reflectance}};
    const PlainDiffuseBsdf<N> plain{Lambertian<N>{reflectance}};
    ASSERT_EQ(plain.is_specular(), general.is_specular());
    ASSERT_EQ(plain.uses_lobe_sample(), general.uses_lobe_sample());
    ASSERT_EQ(plain.uses_direction_sample(), general.uses_direction_sample());
    ASSERT_EQ(plain.is_dispersive(), general.is_dispersive());

    const Vec3f wo = any_direction(rng), wi = any_direction(rng);
    for (const bool want_pdf : {false, true}) {
      float pdf_general = -1.0f, pdf_plain = -1.0f;  // left alone unless written
      const auto f_general = general.eval_with_pdf(wo, wi, want_pdf, pdf_general);
      const auto f_plain = plain.eval_with_pdf(wo, wi, want_pdf, pdf_plain);
      ASSERT_TRUE(same_bits(f_plain, f_general)) << "trial " << trial;
      ASSERT_TRUE(same_bits(pdf_plain, pdf_general)) << "trial " << trial;
    }

    const float u_lobe = rng.next_float();
    const Vec2f u(rng.next_float(), rng.next_float());
    const auto s_general = general.sample(wo, u_lobe, u);
    const auto s_plain = plain.sample(wo, u_lobe, u);
    ASSERT_EQ(s_plain.has_value(), s_general.has_value()) << "trial " << trial;
    if (!s_plain) continue;
    ASSERT_TRUE(same_bits(s_plain->wi.x, s_general->wi.x) && same_bits(s_plain->wi.y, s_general->wi.y) &&
                same_bits(s_plain->wi.z, s_general->wi.z))
        << "trial " << trial;
    ASSERT_TRUE(same_bits(s_plain->f, s_general->f)) << "trial " << trial;
    ASSERT_TRUE(same_bits(s_plain->pdf, s_general->pdf)) << "trial " << trial;
    ASSERT_TRUE(same_bits(s_plain->eta, s_general->eta)) << "trial " << trial;
    ASSERT_EQ(s_plain->is_specular, s_general->is_specular);
    ASSERT_EQ(s_plain->is_transmission, s_general->is_transmission);
    ASSERT_EQ(s_plain->dispersive, s_general->dispersive);
  }
}

TEST(PlainDiffuseBsdf, SameBitsAsABsdfOfTheLambertianLobe) {
  expect_same_answers<3>();
  expect_same_answers<4>();
  expect_same_answers<8>();
}

}  // namespace
}  // namespace prism::bsdf
