#pragma once
// Microfacet-based normal mapping (Schüßler, Heitz, Hanika, Dachsbacher 2017, "Microfacet-
// based Normal Mapping for Robust Monte Carlo Path Tracing", ACM TOG 36(6)).
//
// Classic normal mapping shades with a normal no surface has: the cosine it integrates
// against is not the surface's, directions below the real surface are thrown away, and a
// white Lambertian floor under a white sky comes out darker than the sky. This model keeps
// the mapped normal ωp but makes it a facet of a real microsurface, a sawtooth of two facets
// whose area-weighted mean normal is the unperturbed normal n (local +z here):
//   facet p, normal ωp, area 1/cos θp per unit of macro area (its projection is the macro
//   area), carrying the material's own BSDF;
//   facet t, the "tangent facet": a vertical wall with normal ωt = −(ωp.x, ωp.y, 0)/sin θp,
//   area tan θp, so that the horizontal parts of the two normals cancel. It is a perfect
//   mirror.
// Seen from ω (ω·n > 0) the facets' projected areas are
//   a_p(ω) = ⟨ω, ωp⟩⁺ / cos θp,   a_t(ω) = ⟨ω, ωt⟩⁺ tan θp,
// a ray from ω lands on p with probability λp(ω) = a_p / (a_p + a_t), and a direction ω
// leaving facet p escapes (is not blocked by the wall) with probability
//   G1(ω) = min(1, ω.z / (a_p(ω) + a_t(ω)))   (0 for ω.z ≤ 0).
// A blocked direction reaches the wall and leaves mirrored in the wall's plane,
// m(ω) = ω − 2 ⟨ω, ωt⟩ ωt (which keeps ω.z).
//
// A path on the microsurface is a random walk (the paper's sampling): it lands on p (seen
// directly, or through the wall, which always sends it down onto p), scatters by p's BSDF
// into u, escapes with probability G1(u), or else meets the wall and leaves as m(u), which
// escapes with probability G1(m(u)) (the wall's front faces p, so the same test applies) or
// falls back onto p, and so on. With an albedo-1 facet BSDF no energy is lost: the walk
// ends only by escaping (or after kMaxWalkEvents facet events, see there).
//
// eval() and pdf() are the walk's first facet event only (the paper's explicit paths):
// with v = ωo or m(ωo) the direction facet p is seen in, and u = ωi or m(ωi) the direction
// it is lit from,
//   f₁(ωo, ωi) cos θi = Σ_v P(v) Σ_u P(u) f_p(v, u) ⟨u, ωp⟩,
//   P(ωo) = λp(ωo), P(m(ωo)) = 1 − λp(ωo), P(ωi) = G1(ωi), P(m(ωi)) = (1 − G1(m(ωi))) G1(ωi),
// and pdf₁ the same sum with p's pdf in place of f_p ⟨u, ωp⟩: exactly the density of the
// walks that end after one facet event. sample() returns those walks with f = f₁ and
// pdf = pdf₁ (light sampling estimates f₁ too, and MIS combines the two), and the longer
// walks flagged is_specular with their own weight: light sampling does not estimate that
// remainder, so a light they reach counts in full. The sum is the whole BSDF, unbiased;
// only delta lights, which no sampled direction reaches, miss the remainder.
#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include "prism/bsdf/bsdf_sample.h"
#include "prism/core/frame.h"
#include "prism/core/pcg32.h"
#include "prism/core/sample_stream.h"

namespace prism::bsdf {

class NormalMapMicrosurface {
 public:
  // The microsurface of the mapped frame `facet` given in the unperturbed shading frame's
  // coordinates (facet.n = ωp). Nothing when ωp is (within float precision) the unperturbed
  // normal, or not above it: there is no wall to build, the facet's BSDF is the surface's.
  static std::optional<NormalMapMicrosurface> make(const Frame& facet) {
    const Vec3f& wp = facet.n;
    const float sin_p = std::sqrt(wp.x * wp.x + wp.y * wp.y);
    if (!(wp.z > 0.0f) || !(sin_p > 1e-5f)) return std::nullopt;
    NormalMapMicrosurface m;
    m.facet_ = facet;
    m.wt_ = Vec3f(-wp.x / sin_p, -wp.y / sin_p, 0.0f);
    m.facet_area_ = 1.0f / wp.z;
    m.wall_area_ = sin_p / wp.z;
    return m;
  }

  // The same from the unmapped and the mapped shading frames, both in world space.
  static std::optional<NormalMapMicrosurface> between(const Frame& unmapped, const Frame& mapped) {
    return make(Frame{unmapped.to_local(mapped.s), unmapped.to_local(mapped.t), unmapped.to_local(mapped.n)});
  }

  const Frame& facet() const { return facet_; }
  const Vec3f& wall_normal() const { return wt_; }

  float facet_projected_area(const Vec3f& w) const { return std::max(0.0f, dot(w, facet_.n)) * facet_area_; }
  float wall_projected_area(const Vec3f& w) const { return std::max(0.0f, dot(w, wt_)) * wall_area_; }
  // λp(ω), for ω above the macro surface.
  float facet_probability(const Vec3f& w) const {
    const float a_p = facet_projected_area(w);
    return a_p / (a_p + wall_projected_area(w));
  }
  // G1(ω): a direction leaving facet p escapes past the wall.
  float escape_probability(const Vec3f& w) const {
    if (!(w.z > 0.0f)) return 0.0f;
    return std::min(1.0f, w.z / (facet_projected_area(w) + wall_projected_area(w)));
  }
  // m(ω): the mirror image in the wall's plane (keeps ω.z).
  Vec3f mirrored(const Vec3f& w) const { return w - wt_ * (2.0f * dot(w, wt_)); }

 private:
  Frame facet_;
  Vec3f wt_;
  float facet_area_ = 1.0f, wall_area_ = 0.0f;
};

// A reflection BSDF `Facet` (eval/pdf/sample in its own local frame, bsdf.h's conventions)
// on facet p of a normal-mapped microsurface, in the unperturbed shading frame (z = n).
// Two-sided like the reflection lobes it wraps: for ωo below the surface the whole
// microsurface is mirrored through z = 0. Both references must outlive this object.
template <int N, class Facet>
class MicrofacetNormalMapped {
 public:
  using Spectrum = color::SampledSpectrum<N>;

  MicrofacetNormalMapped(const Facet& facet_bsdf, const NormalMapMicrosurface& surface)
      : bsdf_(facet_bsdf), surface_(surface) {}

  Spectrum eval(Vec3f wo, Vec3f wi) const {
    if (wo.z < 0.0f) {
      wo = flip_z(wo);
      wi = flip_z(wi);
    }
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return Spectrum(0.0f);
    Spectrum sum(0.0f);
    routes(wo, wi, [&](const Vec3f& v, const Vec3f& u, float probability) {
      const Vec3f u_facet = surface_.facet().to_local(u);
      sum += bsdf_.eval(surface_.facet().to_local(v), u_facet) * (probability * std::max(0.0f, u_facet.z));
    });
    return sum * (1.0f / wi.z);
  }

  float pdf(Vec3f wo, Vec3f wi) const {
    if (wo.z < 0.0f) {
      wo = flip_z(wo);
      wi = flip_z(wi);
    }
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    float sum = 0.0f;
    routes(wo, wi, [&](const Vec3f& v, const Vec3f& u, float probability) {
      sum += probability * bsdf_.pdf(surface_.facet().to_local(v), surface_.facet().to_local(u));
    });
    return sum;
  }

  // Facet events after which a walk is dropped. Steep tilts make long walks: with an
  // albedo-1 Lambertian facet seen from above, 32 events dropped 0.25 % of the walks at 80°
  // and 5 % at 85°; 128 dropped none of 2·10⁵ at either.
  static constexpr int kMaxWalkEvents = 128;

  // u_facet.x picks the facet ωo sees (p, or p through the wall), u_facet.y whether the
  // first scattered direction escapes; u_lobe and u drive p's first scattering. A longer
  // walk draws its further numbers from a PCG32 stream seeded by these (as pbrt-v4's
  // layered BSDFs do), so the result stays a function of the sample's numbers.
  std::optional<BsdfSample<N>> sample(Vec3f wo, float u_lobe, Vec2f u, Vec2f u_facet) const {
    const bool flipped = wo.z < 0.0f;
    if (flipped) wo = flip_z(wo);
    if (!(wo.z > 0.0f)) return std::nullopt;
    const NormalMapMicrosurface& m = surface_;
    Vec3f v = u_facet.x < m.facet_probability(wo) ? wo : m.mirrored(wo);
    Pcg32 rng(mix64((static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(u.x)) << 32) ^
                    std::bit_cast<std::uint32_t>(u.y)),
              (static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(u_lobe)) << 32) ^
                  std::bit_cast<std::uint32_t>(u_facet.y));
    Spectrum weight(1.0f);
    bool specular = false;
    for (int event = 0; event < kMaxWalkEvents; ++event) {
      const bool first = event == 0;
      const Vec3f v_facet = m.facet().to_local(v);
      const auto s = first ? bsdf_.sample(v_facet, u_lobe, u)
                           : bsdf_.sample(v_facet, rng.next_float(), {rng.next_float(), rng.next_float()});
      if (!s || s->is_transmission || !(s->pdf > 0.0f)) return std::nullopt;
      weight *= s->f * (std::abs(s->wi.z) / s->pdf);
      specular = specular || s->is_specular;
      Vec3f wi = m.facet().to_world(s->wi);
      bool escaped = (first ? u_facet.y : rng.next_float()) < m.escape_probability(wi);
      if (!escaped) {
        wi = m.mirrored(wi);  // met the wall
        escaped = rng.next_float() < m.escape_probability(wi);
      }
      if (!escaped) {
        v = -wi;  // fell back onto p
        continue;
      }
      BsdfSample<N> out = *s;
      out.wi = flipped ? flip_z(wi) : wi;
      if (first && !specular) {
        out.f = eval(wo, wi);
        out.pdf = pdf(wo, wi);
      } else {
        // A delta facet, or a longer walk: the walk's weight f |cos θi| / pdf, with pdf 1.
        out.f = weight * (1.0f / wi.z);
        out.pdf = 1.0f;
        out.is_specular = true;
      }
      return out;
    }
    return std::nullopt;
  }

 private:
  // Calls visit(v, u, P(v) P(u)) for each of the four routes from ωo to ωi with nonzero
  // probability (both above the surface).
  template <class Visit>
  void routes(const Vec3f& wo, const Vec3f& wi, const Visit& visit) const {
    const float seen_directly = surface_.facet_probability(wo);
    const Vec3f wi_mirrored = surface_.mirrored(wi);
    const float lit_directly = surface_.escape_probability(wi);
    const float lit_via_wall = (1.0f - surface_.escape_probability(wi_mirrored)) * lit_directly;
    const auto from = [&](const Vec3f& v, float p_v) {
      if (!(p_v > 0.0f)) return;
      if (lit_directly > 0.0f) visit(v, wi, p_v * lit_directly);
      if (lit_via_wall > 0.0f) visit(v, wi_mirrored, p_v * lit_via_wall);
    };
    from(wo, seen_directly);
    from(surface_.mirrored(wo), 1.0f - seen_directly);
  }

  const Facet& bsdf_;
  const NormalMapMicrosurface& surface_;
};

// The model over a shading point's BSDF (bsdf.h), compiled once in
// microfacet_normal_mapping.cpp for the integrator's spectrum sizes (3, 4, 8): shading
// without a map then keeps its own inlined BSDF calls.
template <int N>
struct Bsdf;
template <int N>
color::SampledSpectrum<N> microsurface_eval(const Bsdf<N>& facet, const NormalMapMicrosurface& surface,
                                            const Vec3f& wo, const Vec3f& wi);
template <int N>
float microsurface_pdf(const Bsdf<N>& facet, const NormalMapMicrosurface& surface, const Vec3f& wo, const Vec3f& wi);
template <int N>
std::optional<BsdfSample<N>> microsurface_sample(const Bsdf<N>& facet, const NormalMapMicrosurface& surface,
                                                 const Vec3f& wo, float u_lobe, Vec2f u, Vec2f u_facet);

}  // namespace prism::bsdf
