// Microfacet-based normal mapping (bsdf/microfacet_normal_mapping.h, Schüßler et al. 2017):
// the two-facet microsurface against the sawtooth it stands for (mean normal, visible
// fractions from 2D ray geometry), the random walk against the white furnace (an albedo-1
// facet BSDF loses nothing), and sample() against pdf() by chi-square for the walks that
// light sampling also estimates.
#include "prism/bsdf/microfacet_normal_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/bsdf/bsdf.h"
#include "prism/core/pcg32.h"
#include "support/chi_square.h"

namespace prism::bsdf {
namespace {

using Spectrum3 = color::SampledSpectrum<3>;
constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;

Vec3f float_direction_at(float theta_deg, float phi_deg) {
  const float t = theta_deg * kDegree, p = phi_deg * kDegree;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// The mapped normal tilted by `tilt_deg` towards +x (so the wall faces −x).
NormalMapMicrosurface surface_tilted(float tilt_deg) {
  const Vec3f wp = float_direction_at(tilt_deg, 0.0f);
  const auto facet = Frame::from_normal_and_tangent(wp, Vec3f(1, 0, 0));
  return *NormalMapMicrosurface::make(*facet);
}

TEST(MicrofacetNormalMapping, TheFacetsMeanNormalIsTheSurfaceNormal) {
  for (const float tilt : {5.0f, 30.0f, 60.0f, 85.0f}) {
    for (const float phi : {0.0f, 130.0f}) {
      const Vec3f wp = float_direction_at(tilt, phi);
      const auto m = *NormalMapMicrosurface::make(*Frame::from_normal_and_tangent(wp, Vec3f(1, 0, 0)));
      // Per unit of macro area: facet p projects to exactly that unit, and the areas
      // weight the two normals to n, so a_p(ω) + a_t(ω) = ω·n whenever both face ω.
      const Vec3f normal_sum =
          wp * m.facet_projected_area(wp) + m.wall_normal() * m.wall_projected_area(m.wall_normal());
      EXPECT_NEAR(normal_sum.x, 0.0f, 1e-5f);
      EXPECT_NEAR(normal_sum.y, 0.0f, 1e-5f);
      EXPECT_NEAR(normal_sum.z, 1.0f, 1e-5f);
      Pcg32 rng(7, 3);
      for (int i = 0; i < 1000; ++i) {
        const float z = rng.next_float(), a = 2.0f * std::numbers::pi_v<float> * rng.next_float();
        const float r = std::sqrt(1.0f - z * z);
        const Vec3f w(r * std::cos(a), r * std::sin(a), z);
        if (dot(w, wp) > 0.0f && dot(w, m.wall_normal()) > 0.0f) {
          EXPECT_NEAR(m.facet_projected_area(w) + m.wall_projected_area(w), w.z, 1e-5f);
          EXPECT_NEAR(m.escape_probability(w), 1.0f, 1e-5f);
        }
      }
    }
  }
}

// A 2D sawtooth: slopes rising at θp towards −x, each ending in a vertical wall at its low
// (+x) end. Ray geometry alone gives the escape fractions, independently of the projected
// area formulas:
//  - leaving a uniform point of a slope towards the wall at elevation β, a ray clears the
//    wall's top iff the point lies at least tan θp / (tan θp + tan β) of the slope's width
//    from the wall's base: it escapes with probability tan β / (tan θp + tan β);
//  - leaving a uniform point of the wall away from it at elevation β < θp, a ray clears the
//    slope ahead iff it starts above 1 − tan β / tan θp of the wall's height: probability
//    tan β / tan θp (1 for β ≥ θp).
TEST(MicrofacetNormalMapping, EscapeProbabilitiesAreTheSawtoothsRayGeometry) {
  for (const float tilt : {20.0f, 45.0f, 70.0f}) {
    const NormalMapMicrosurface m = surface_tilted(tilt);
    const double tan_p = std::tan(tilt * kDegree);
    for (const float beta : {5.0f, 15.0f, 35.0f, 60.0f, 85.0f}) {
      const double tan_b = std::tan(beta * kDegree);
      const Vec3f towards_wall(std::cos(beta * kDegree), 0.0f, std::sin(beta * kDegree));
      EXPECT_NEAR(m.escape_probability(towards_wall), tan_b / (tan_p + tan_b), 2e-6) << tilt << " " << beta;
      const Vec3f away(-std::cos(beta * kDegree), 0.0f, std::sin(beta * kDegree));
      EXPECT_NEAR(m.escape_probability(away), beta >= tilt ? 1.0 : tan_b / tan_p, 2e-6) << tilt << " " << beta;
    }
  }
}

TEST(MicrofacetNormalMapping, NoMicrosurfaceWithoutATilt) {
  EXPECT_FALSE(NormalMapMicrosurface::make(Frame::from_normal(Vec3f(0, 0, 1))).has_value());
  EXPECT_FALSE(NormalMapMicrosurface::make(Frame::from_normal(Vec3f(0.6f, 0, -0.8f))).has_value());
}

// Mean of f |cos θi| / pdf over sample(): the directional albedo.
double albedo(const MicrofacetNormalMapped<3, Bsdf<3>>& b, const Vec3f& wo, int n, std::uint64_t seed) {
  Pcg32 rng(seed, 11);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const float u_lobe = rng.next_float();
    const Vec2f u(rng.next_float(), rng.next_float()), u_facet(rng.next_float(), rng.next_float());
    if (const auto s = b.sample(wo, u_lobe, u, u_facet)) sum += s->f[0] * std::abs(s->wi.z) / s->pdf;
  }
  return sum / n;
}

// An albedo-1 facet BSDF on the microsurface keeps all its energy: every walk ends by
// escaping with weight 1 unless it is dropped after kMaxWalkEvents events (none were in
// 2·10⁵ walks at 85°). Classic normal
// mapping keeps (1 + cos θp)/2 of it for a Lambertian facet (0.59 at 80°). 2·10⁴ walks: a
// walk's weight is 1 or 0, so the mean's standard error is below √(10⁻⁴/2·10⁴) ≈ 10⁻⁴ if
// 10⁻⁴ of walks were dropped; 10⁻³ leaves room for that and is far from any real loss.
TEST(MicrofacetNormalMapping, TheWalkPassesTheWhiteFurnace) {
  const Bsdf<3> lambert{Lambertian<3>{Spectrum3(1.0f)}};
  const Bsdf<3> mirror{SpecularReflection<3>{Spectrum3(1.0f)}};
  std::uint64_t seed = 1;
  for (const float tilt : {10.0f, 40.0f, 65.0f, 80.0f})
    for (const Bsdf<3>* facet : {&lambert, &mirror}) {
      const NormalMapMicrosurface surface = surface_tilted(tilt);
      const MicrofacetNormalMapped<3, Bsdf<3>> b(*facet, surface);
      for (const float theta : {0.0f, 45.0f, 85.0f})
        for (const float phi : {0.0f, 90.0f, 180.0f})
          EXPECT_NEAR(albedo(b, float_direction_at(theta, phi), 20000, ++seed), 1.0, 1e-3)
              << "tilt " << tilt << " wo " << theta << "/" << phi;
      // Two-sided: the surface seen from below is the mirrored microsurface.
      EXPECT_NEAR(albedo(b, float_direction_at(135.0f, 40.0f), 20000, ++seed), 1.0, 1e-3);
    }
}

// The walks that end after one facet event (returned as non-delta samples) are drawn with
// density pdf(); the longer ones are delta samples and count as absent mass here.
constexpr int kNormalMappingChiSquareTests = 2 * 2 * 4;
TEST(MicrofacetNormalMapping, FirstEventSamplesFollowPdf) {
  const Bsdf<3> lambert{Lambertian<3>{Spectrum3(0.8f)}};
  const Bsdf<3> conductor{RoughConductor<3>{MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f),
                                            ConductorFresnel<3>::schlick(Spectrum3(0.9f))}};
  const double alpha = test::sidak_alpha(test::kAlphaTotal, kNormalMappingChiSquareTests);
  unsigned long long seed = 5;
  for (const Bsdf<3>* facet : {&lambert, &conductor})
    for (const float tilt : {30.0f, 60.0f}) {
      const NormalMapMicrosurface surface = surface_tilted(tilt);
      const MicrofacetNormalMapped<3, Bsdf<3>> b(*facet, surface);
      for (const Vec3f wo : {float_direction_at(0, 0), float_direction_at(50, 0), float_direction_at(50, 180), float_direction_at(75, 90)}) {
        Pcg32 rng(++seed, 3);
        const auto h = test::spherical_histogram(
            [&](Vec2f u, Vec3f& wi) {
              const Vec2f u_facet(rng.next_float(), rng.next_float());
              const auto s = b.sample(wo, rng.next_float(), u, u_facet);
              if (!s || s->is_specular) return false;
              wi = s->wi;
              return true;
            },
            [&](const Vec3f& wi) { return static_cast<double>(b.pdf(wo, wi)); }, 20, 40, 200'000, seed, 16);
        const test::ChiSquareResult r = test::chi_square_test(h.observed, h.expected);
        EXPECT_GT(r.p_value, alpha) << "tilt " << tilt << " wo " << wo.x << "," << wo.y << "," << wo.z << ": "
                                    << r.message;
      }
    }
}

// What light sampling evaluates is the same first-event BSDF: a sample's f and pdf are
// eval() and pdf() at its direction, and from below the surface both mirror.
TEST(MicrofacetNormalMapping, SamplesCarryEvalAndPdfAndTheBackSideMirrors) {
  const Bsdf<3> lambert{Lambertian<3>{Spectrum3(0.8f)}};
  const NormalMapMicrosurface surface = surface_tilted(50.0f);
  const MicrofacetNormalMapped<3, Bsdf<3>> b(lambert, surface);
  const Vec3f wo = float_direction_at(40.0f, 30.0f);
  Pcg32 rng(9, 9);
  int first_events = 0;
  for (int i = 0; i < 200; ++i) {
    const auto s = b.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                            {rng.next_float(), rng.next_float()});
    if (!s || s->is_specular) continue;
    ++first_events;
    EXPECT_FLOAT_EQ(s->f[0], b.eval(wo, s->wi)[0]);
    EXPECT_FLOAT_EQ(s->pdf, b.pdf(wo, s->wi));
    const Vec3f below_o = flip_z(wo), below_i = flip_z(s->wi);
    EXPECT_FLOAT_EQ(b.eval(below_o, below_i)[0], s->f[0]);
    EXPECT_FLOAT_EQ(b.pdf(below_o, below_i), s->pdf);
  }
  EXPECT_GT(first_events, 50);
}

}  // namespace
}  // namespace prism::bsdf
