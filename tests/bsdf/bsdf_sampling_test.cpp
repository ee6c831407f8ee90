// Every BSDF's sample() against its pdf(): chi-square goodness of fit over the whole sphere
// (reflection and transmission), in a stretched space around the lobe for rough lobes
// (see stretched_chi_square.h). Delta lobes are checked by their discrete choice.
#include "prism/bsdf/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "bsdf/bsdf_test_helpers.h"
#include "bsdf/stretched_chi_square.h"
#include "prism/core/pcg32.h"

namespace prism::bsdf {
namespace {

using Spectrum3 = color::SampledSpectrum<3>;
using test_helpers::direction_at;
using test_helpers::rgb;
// Histograms drawn in this file (Šidák split): lambert 4, conductor 5 kinds × 9 = 45,
// metallic-roughness 7 × 3 = 21, rough dielectric 3 α × 5 wo × 2 halves = 30, dispersive 2,
// smooth-dielectric lobe choice 4, coated lobes 3 bases × 2 coat roughnesses × 3 wo = 18 plus
// a smooth coat's non-delta part 3, anisotropic lobes 12 + 2 + 4, tilted coats 6.
constexpr int kBsdfChiSquareTests = 4 + 45 + 21 + 30 + 2 + 4 + 18 + 3 + 15 + 18 + 6;
constexpr long kSamples = 100'000;

// Draws (u_lobe, u) from the harness's 2D uniform by splitting u.x: the high bits pick the
// lobe, the rest drive the direction (both uniform and independent to float precision).
struct Uniforms {
  float u_lobe;
  Vec2f u;
};
Uniforms split(Vec2f u, unsigned long long& state) {
  // A second, independent stream for the lobe choice (xorshift on a per-test state).
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return {static_cast<float>(state >> 40) * 0x1p-24f, u};
}

// Chi-square of bsdf.sample(wo) vs bsdf.pdf(wo, ·), restricted to the hemisphere with
// sign `side` relative to wo (0: whole sphere), stretched by `s` around `axis`.
// `simpson_intervals` per bin and axis integrate the pdf (chi_square.h): densities that
// jump inside a bin need more than the default 8.
double bsdf_p_value(const Bsdf<3>& bsdf, const Vec3f& wo, Vec3f axis, float s, int side,
                    unsigned long long seed, int simpson_intervals = 8) {
  // Grazing wo: the lobe presses against the horizon; keep the horizon a bin boundary (axis
  // z, no stretch) and resolve the lobe with a 4× finer grid instead (stretched_chi_square.h).
  int cos_bins = 20, phi_bins = 40;
  const float s_in = s;
  if (std::abs(wo.z) < 0.2f) {
    axis = Vec3f(0, 0, 1);
    s = 1.0f;
    // Sharp grazing lobes (s < 0.2: α = 0.05) span only a few bins even then: 16× finer.
    cos_bins = s_in < 0.2f ? 80 : 40;
    phi_bins = s_in < 0.2f ? 160 : 80;
  }
  unsigned long long state = seed * 0x9E3779B97F4A7C15ull + 1;
  auto in_side = [&](const Vec3f& w) { return side == 0 || (w.z * wo.z > 0.0f) == (side > 0); };
  const auto r = test::stretched_chi_square(
      [&](Vec2f u, Vec3f& wi) {
        const auto [u_lobe, u2] = split(u, state);
        const auto smp = bsdf.sample(wo, u_lobe, u2);
        if (!smp || !in_side(smp->wi)) return false;
        wi = smp->wi;
        return true;
      },
      [&](const Vec3f& wi) { return in_side(wi) ? double(bsdf.pdf(wo, wi)) : 0.0; }, axis, s, kSamples,
      seed, cos_bins, phi_bins, simpson_intervals);
  if (r.p_value <= test::sidak_alpha(test::kAlphaTotal, kBsdfChiSquareTests)) ADD_FAILURE() << r.message << " (wo = " << wo.x << ' ' << wo.y << ' ' << wo.z
                  << ", stretch " << s << ", side " << side << ", seed " << seed << ')';
  return r.p_value;
}

const float kAlphas[] = {0.05f, 0.3f, 0.8f};
const double kThetas[] = {0.0, 45.0, 85.0};

TEST(BsdfSampling, LambertianMatchesPdf) {
  Bsdf<3> b{Lambertian<3>{Spectrum3(0.7f)}};
  int seed = 1;
  for (const Vec3f& wo : {direction_at(0), direction_at(45), direction_at(85), -direction_at(30, 40)})
    EXPECT_GT(bsdf_p_value(b, wo, Vec3f(0, 0, 1), 1.0f, 0, ++seed), 0.0) << wo.z;
}

TEST(BsdfSampling, RoughConductorMatchesPdf) {
  const MicrofacetDistribution kinds[] = {
      MicrofacetDistribution::isotropic(MicrofacetType::ggx, 1, MicrofacetSampling::visible_normals),
      MicrofacetDistribution::isotropic(MicrofacetType::ggx, 1, MicrofacetSampling::spherical_caps),
      MicrofacetDistribution::isotropic(MicrofacetType::ggx, 1, MicrofacetSampling::ndf),
      MicrofacetDistribution::isotropic(MicrofacetType::beckmann, 1),
      MicrofacetDistribution::isotropic(MicrofacetType::blinn_phong, 1)};
  int seed = 100;
  for (auto d : kinds)
    for (float a : kAlphas)
      for (double theta : kThetas) {
        d.alpha_x = d.alpha_y = a;
        Bsdf<3> b{RoughConductor<3>{d, ConductorFresnel<3>::schlick(Spectrum3(0.9f))}};
        const Vec3f wo = direction_at(theta, 30.0);
        const Vec3f mirror(-wo.x, -wo.y, wo.z);
        const double p = bsdf_p_value(b, wo, mirror, 2.0f * a, 0, ++seed);
        RecordProperty("conductor_" + std::to_string(int(d.type)) + "_" + std::to_string(int(d.sampling)) + "_" +
                           std::to_string(a) + "_" + std::to_string(theta),
                       std::to_string(p));
      }
}

TEST(BsdfSampling, MetallicRoughnessMatchesPdf) {
  int seed = 200;
  // (metallic, roughness, dielectric F0, specular weight): the last two with
  // KHR_materials_ior / KHR_materials_specular's generalisation (metallic_roughness.h).
  struct Case {
    float metallic, roughness, f0 = MetallicRoughness<3>::kDielectricF0, weight = 1.0f;
  };
  const Case cases[] = {{0.0f, 0.25f},          {0.0f, 0.95f}, {0.5f, 0.6f}, {1.0f, 0.25f}, {1.0f, 0.95f},
                        {0.0f, 0.3f, 0.2f, 0.5f}, {0.4f, 0.7f, 0.11f, 0.2f}};
  for (const auto& [metallic, roughness, f0, weight] : cases) {
      auto m = MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), metallic, roughness, f0, weight);
      for (double theta : kThetas) {
        const Vec3f wo = direction_at(theta, 120.0);
        // Two lobes: a broad diffuse one and the specular one; stretch moderately around the
        // specular direction so both stay resolved.
        const float s = std::max(0.3f, 2.0f * m.distribution.alpha_x);
        bsdf_p_value(Bsdf<3>{m}, wo, Vec3f(-wo.x, -wo.y, wo.z), s, 0, ++seed);
      }
    }
  // A tinted F0 (KHR_materials_specular's colour): the lobe probabilities come from its mean,
  // the diffuse weight from its largest component.
  const auto tinted = MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.2f, 0.5f,
                                                           rgb(0.3f, 0.05f, 0.0f), 0.3f, 0.7f);
  // A thin film (iridescence) over both bases: the probabilities come from its colours.
  auto filmed = MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.4f, 0.3f);
  filmed.film.weight = 0.9f;
  filmed.film.thickness_nm = 300.0f;
  filmed.film.eta_film = 2.0f;
  filmed.film.wavelength_nm = rgb(630.0f, 532.0f, 465.0f);
  for (double theta : kThetas) {
    const Vec3f wo = direction_at(theta, 120.0);
    bsdf_p_value(Bsdf<3>{tinted}, wo, Vec3f(-wo.x, -wo.y, wo.z), 0.5f, 0, ++seed);
    bsdf_p_value(Bsdf<3>{filmed}, wo, Vec3f(-wo.x, -wo.y, wo.z), 0.6f, 0, ++seed);
  }
}

// Rough dielectric (η = 1.5, GGX VNDF): each wo is tested twice, once on the reflection
// hemisphere stretched around the mirror direction and once on the transmission hemisphere
// stretched around the smooth refraction direction, so both lobes are resolved. Samples
// that fail (reflected/refracted into the wrong hemisphere) are absent mass, matching pdf().
Vec3f transmission_axis(const Vec3f& wo, float eta, float& s) {
  Vec3f wt;
  if (refract(wo, Vec3f(0, 0, 1), eta, wt)) return wt;
  s = 1.0f;  // beyond the critical angle: a broad, grazing lobe; no stretch
  return Vec3f(0, 0, wo.z > 0 ? -1.0f : 1.0f);
}

TEST(BsdfSampling, RoughDielectricMatchesPdf) {
  int seed = 300;
  const Vec3f wos[] = {direction_at(0), direction_at(45, 10), direction_at(85, 10), -direction_at(30, 70),
                       -direction_at(60, 70)};  // the last two from inside; 60° is past TIR
  for (float a : kAlphas)
    for (const Vec3f& wo : wos) {
      Dielectric<3> d{Spectrum3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, a)};
      const Bsdf<3> b{d};
      bsdf_p_value(b, wo, Vec3f(-wo.x, -wo.y, wo.z), 2.0f * a, +1, ++seed);
      float s = a;
      const Vec3f axis = transmission_axis(wo, 1.5f, s);
      // From grazing wo the transmission lobe ends along a curve with a jump, not a fade:
      // it is the image of the microfacet horizon (h.z → 0), where GGX's D stays α²/π and
      // the VNDF stays finite, so pdf() drops from a finite value to 0 inside the bins it
      // crosses. The default 8 Simpson intervals integrate such a bin to O(1/8) of the
      // jump's share; at α = 0.8 that was a systematic misfit (p 5e-8…8e-4 over 6 seeds at
      // 400k samples). With 64 intervals the same seeds give p 0.25–0.67 (sampling and pdf
      // agree; measured in h space too: the sampled mass of the edge bin matches the pdf
      // integrated over microfacet normals to 1.6σ of 20M samples).
      const bool grazing = std::abs(wo.z) < 0.2f;
      bsdf_p_value(b, wo, axis, s, -1, ++seed, grazing ? 64 : 8);
    }
}

// Anisotropic lobes (αx ≠ αy: KHR_materials_anisotropy, pbrt-v4's uroughness/vroughness,
// render/anisotropy.h), seen from azimuths off both axes so that a swapped or mixed-up
// axis in sampling, eval or pdf shows: conductors by every sampling method, a
// metallic-roughness lobe and rough glass (reflection and transmission). The grid is
// stretched for the wide axis, so along the narrow one (α 0.05–0.1) the pdf peaks inside a
// bin: 8 Simpson intervals per bin misintegrated it (p down to 1e-256 on 10 of 18
// histograms); 64 resolve it (all 18 pass).
TEST(BsdfSampling, AnisotropicLobesMatchPdf) {
  int seed = 900;
  const std::pair<float, float> stretches[] = {{0.1f, 0.5f}, {0.6f, 0.05f}};
  const Vec3f wos[] = {direction_at(40, 30), direction_at(70, 115)};
  const MicrofacetDistribution kinds[] = {
      MicrofacetDistribution::isotropic(MicrofacetType::ggx, 1, MicrofacetSampling::visible_normals),
      MicrofacetDistribution::isotropic(MicrofacetType::ggx, 1, MicrofacetSampling::spherical_caps),
      MicrofacetDistribution::isotropic(MicrofacetType::beckmann, 1)};
  for (auto d : kinds)
    for (const auto& [ax, ay] : stretches)
      for (const Vec3f& wo : wos) {
        d.alpha_x = ax;
        d.alpha_y = ay;
        const Bsdf<3> b{RoughConductor<3>{d, ConductorFresnel<3>::schlick(Spectrum3(0.9f))}};
        bsdf_p_value(b, wo, Vec3f(-wo.x, -wo.y, wo.z), 2.0f * std::max(ax, ay), 0, ++seed, 64);
      }
  auto m = MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.5f, 0.3f);
  m.distribution.alpha_x = 0.6f;
  for (const Vec3f& wo : wos) bsdf_p_value(Bsdf<3>{m}, wo, Vec3f(-wo.x, -wo.y, wo.z), 1.2f, 0, ++seed, 64);
  const MicrofacetDistribution glass_d{MicrofacetType::ggx, 0.4f, 0.08f};
  const Bsdf<3> glass{Dielectric<3>{Spectrum3(1.5f), glass_d}};
  for (const Vec3f& wo : wos) {
    bsdf_p_value(glass, wo, Vec3f(-wo.x, -wo.y, wo.z), 0.8f, +1, ++seed, 64);
    float s = 0.4f;
    const Vec3f axis = transmission_axis(wo, 1.5f, s);
    bsdf_p_value(glass, wo, axis, s, -1, ++seed, 64);
  }
}

TEST(BsdfSampling, DispersiveDielectricSamplesTheHeroWavelength) {
  Dielectric<3> d{rgb(1.50f, 1.52f, 1.54f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f)};
  const Bsdf<3> b{d};
  ASSERT_TRUE(b.is_dispersive());
  const Vec3f wo = direction_at(45, 10);
  bsdf_p_value(b, wo, Vec3f(-wo.x, -wo.y, wo.z), 0.6f, +1, 401);
  float s = 0.3f;
  bsdf_p_value(b, wo, transmission_axis(wo, 1.5f, s), s, -1, 402);
  Pcg32 rng(3, 4);
  int checked = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto smp = b.sample(wo, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    if (!smp) continue;
    ++checked;
    EXPECT_TRUE(smp->dispersive);
    EXPECT_GT(smp->f[0], 0.0f);
    EXPECT_EQ(smp->f[1], 0.0f);
    EXPECT_EQ(smp->f[2], 0.0f);
    // Channel 0 of eval() is what sample() returned.
    EXPECT_NEAR(b.eval(wo, smp->wi)[0], smp->f[0], 1e-4f * smp->f[0]);
  }
  EXPECT_GT(checked, 900);
  const Bsdf<3> constant{Dielectric<3>{Spectrum3(1.5f), d.distribution}};
  EXPECT_FALSE(constant.is_dispersive());
  EXPECT_FALSE(constant.sample(wo, 0.9f, Vec2f(0.3f, 0.4f))->dispersive);
}

// Smooth dielectric: the reflected and refracted directions are exact, and reflection is
// chosen with probability F (2-bin chi-square on 100k choices).
TEST(BsdfSampling, SmoothDielectricChoosesLobesByFresnel) {
  const Bsdf<3> b{Dielectric<3>{Spectrum3(1.5f), MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.0f)}};
  ASSERT_TRUE(b.is_specular());
  Pcg32 rng(5, 6);
  for (const Vec3f& wo : {direction_at(0), direction_at(45), direction_at(85), -direction_at(30)}) {
    const float F = fresnel_dielectric(wo.z, 1.5f);
    constexpr long kChoices = 100'000;
    double reflections = 0;
    for (long i = 0; i < kChoices; ++i) {
      const auto smp = b.sample(wo, rng.next_float(), Vec2f(0.5f, 0.5f));
      ASSERT_TRUE(smp.has_value());
      ASSERT_TRUE(smp->is_specular);
      if (!smp->is_transmission) {
        ++reflections;
        EXPECT_NEAR(length(smp->wi - Vec3f(-wo.x, -wo.y, wo.z)), 0.0f, 1e-6f);
      } else {
        // Snell: η_o sin θo = η_i sin θi.
        const float eta_o = wo.z > 0 ? 1.0f : 1.5f, eta_i = wo.z > 0 ? 1.5f : 1.0f;
        EXPECT_NEAR(eta_o * std::sqrt(1 - wo.z * wo.z), eta_i * std::sqrt(1 - smp->wi.z * smp->wi.z), 1e-5f);
        EXPECT_LT(smp->wi.z * wo.z, 0.0f);
      }
    }
    const double observed[] = {reflections, kChoices - reflections};
    const double expected[] = {kChoices * double(F), kChoices * (1.0 - F)};
    const auto r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kBsdfChiSquareTests)) << r.message;
  }
}

// Clear coats (clearcoat.h) over each reflective base: the mixture of the coat's GGX lobe
// and the base's. Stretched moderately around the mirror direction, where the coat's lobe
// is, so that the broad base lobes stay resolved too.
TEST(BsdfSampling, CoatedLobesMatchPdf) {
  const Bsdf<3>::Lobe bases[] = {
      Lambertian<3>{rgb(0.3f, 0.5f, 0.7f)},
      MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.3f, 0.7f),
      RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.5f), ConductorFresnel<3>::schlick(Spectrum3(0.8f))},
  };
  int seed = 500;
  for (const auto& base : bases)
    for (float coat_roughness : {0.3f, 0.7f})
      for (double theta : kThetas) {
        Bsdf<3> b{base};
        b.coat = Clearcoat::make(1.0f, coat_roughness);
        const Vec3f wo = direction_at(theta, 60.0);
        const float s = std::max(0.3f, 2.0f * coat_roughness * coat_roughness);
        bsdf_p_value(b, wo, Vec3f(-wo.x, -wo.y, wo.z), s, 0, ++seed);
      }
  // Coats with a normal of their own (clearcoatNormalTexture), tilted 20° and 40° from the
  // base's: reflections about the coat's normal, those below the base's surface dropped
  // (failed samples, absent from pdf()).
  for (const double tilt : {20.0, 40.0})
    for (double theta : kThetas) {
      Bsdf<3> b{MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.3f, 0.7f)};
      b.coat = Clearcoat::make(1.0f, 0.3f);
      const float t = static_cast<float>(tilt * std::numbers::pi / 180.0);
      const Frame coat_frame =
          *Frame::from_normal_and_tangent(Vec3f(std::sin(t), 0.0f, std::cos(t)), Vec3f(1, 0, 0));
      b.coat.frame = &coat_frame;
      const Vec3f wo = direction_at(theta, 60.0);
      bsdf_p_value(b, wo, Vec3f(0, 0, 1), 1.0f, 0, ++seed, 32);
    }
  // A smooth coat: its delta samples are left out (as failed samples: absent mass), the rest
  // must follow pdf(), which integrates to 1 − p_c.
  Bsdf<3> smooth{Lambertian<3>{Spectrum3(0.4f)}};
  smooth.coat = Clearcoat::make(1.0f, 0.0f);
  for (double theta : kThetas) {
    const Vec3f wo = direction_at(theta, 60.0);
    unsigned long long state = 77 + static_cast<unsigned long long>(theta);
    const auto r = test::stretched_chi_square(
        [&](Vec2f u, Vec3f& wi) {
          const auto [u_lobe, u2] = split(u, state);
          const auto smp = smooth.sample(wo, u_lobe, u2);
          if (!smp || smp->is_specular) return false;
          wi = smp->wi;
          return true;
        },
        [&](const Vec3f& wi) { return double(smooth.pdf(wo, wi)); }, Vec3f(0, 0, 1), 1.0f, kSamples,
        ++seed, 20, 40, 8);
    EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kBsdfChiSquareTests)) << r.message << " theta " << theta;
  }
}

// Sheens (sheen.h) over diffuse and metallic-roughness bases: the mixture of the sheen's
// uniform hemisphere and the base's lobe; then a coat over a sheen over a metal, the full
// glTF stack. Unstretched: the sheen's samples spread over the whole hemisphere.
TEST(BsdfSampling, SheenedLobesMatchPdf) {
  const Bsdf<3>::Lobe bases[] = {
      Lambertian<3>{rgb(0.3f, 0.5f, 0.7f)},
      MetallicRoughness<3>::from_roughness(rgb(0.2f, 0.5f, 0.9f), 0.3f, 0.4f),
  };
  int seed = 700;
  for (const auto& base : bases)
    for (float r : {0.3f, 0.8f})
      for (double theta : kThetas) {
        Bsdf<3> b{base};
        b.sheen = Sheen<3>::make(rgb(0.9f, 0.7f, 0.5f), r);
        const Vec3f wo = direction_at(theta, 60.0);
        bsdf_p_value(b, wo, Vec3f(0, 0, 1), 1.0f, 0, ++seed);
      }
  for (double theta : kThetas) {
    Bsdf<3> b{MetallicRoughness<3>::from_roughness(rgb(0.8f, 0.6f, 0.3f), 1.0f, 0.5f)};
    b.sheen = Sheen<3>::make(rgb(0.5f, 0.5f, 0.5f), 0.5f);
    b.coat = Clearcoat::make(0.7f, 0.4f);
    const Vec3f wo = direction_at(theta, 60.0);
    bsdf_p_value(b, wo, Vec3f(-wo.x, -wo.y, wo.z), 0.5f, 0, ++seed);
  }
}

TEST(BsdfSampling, MirrorReflectsExactly) {
  const Bsdf<3> b{SpecularReflection<3>{rgb(0.9f, 0.5f, 0.1f)}};
  const Vec3f wo = direction_at(50, 20);
  const auto smp = b.sample(wo, 0.5f, Vec2f(0.5f, 0.5f));
  ASSERT_TRUE(smp && smp->is_specular);
  EXPECT_NEAR(length(smp->wi - Vec3f(-wo.x, -wo.y, wo.z)), 0.0f, 1e-6f);
  // β update f·|cos θi|/pdf is the tint.
  EXPECT_NEAR(smp->f[1] * smp->wi.z / smp->pdf, 0.5f, 1e-6f);
  EXPECT_EQ(b.pdf(wo, smp->wi), 0.0f);
  EXPECT_TRUE(b.eval(wo, smp->wi).is_black());
}

}  // namespace
}  // namespace prism::bsdf
