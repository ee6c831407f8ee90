#pragma once
// Next-event estimation's view of all emitters: emissive triangles, point, spot and
// directional lights. One emitter is chosen with probability proportional to an estimate
// of its emitted power (in lumen-like units), then a point or direction on it.
//
// Textured emitters (Emission::texture): a triangle's power is π L A times the mean of
// Y(colour ⊙ texel)/Y(colour) at 16 stratified points of its uv footprint, plus 1% of the
// texture's mean over its texels. The estimate only steers the selection: any selection probability
// that is positive wherever the emitted radiance can be is unbiased, and the floor keeps
// it positive on triangles whose quadrature points all miss a small bright feature. The
// point on the triangle is chosen by the triangle strategy (scene/triangle_light_sampling.h:
// uniformly by area by default, or in solid angle, optionally warped towards the receiver's
// cosine), and its uv from the barycentrics of the sampled point; the integrator evaluates the
// texture at the sampled uv (finest level) for NEE and at the hit for BSDF-sampled hits,
// so both techniques estimate the same function and MIS stays unbiased. Radiance
// values come from the transport mode (render/color_context.h) by emitter id; this class
// only handles geometry and densities.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "prism/core/bounds.h"
#include "prism/core/branch_free.h"
#include "prism/core/vec.h"
#include "prism/sampling/piecewise_constant.h"
#include "prism/scene/scene.h"
#include "prism/scene/triangle_light_sampling.h"

namespace prism {

struct LightSample {
  // User-provided, so that value-initialisation (std::optional's in-place construction)
  // writes the member initialisers below one by one: as an aggregate the whole 88 bytes
  // are cleared first, which GCC 12 does with `rep stosq` (tens of cycles to start, and
  // NEE builds one sample per path vertex).
  LightSample() {}
  Vec3f wi;                 // unit direction from the shading point towards the light
  float distance = 0.0f;    // to the sampled point; infinity for directional lights
  float pdf = 0.0f;         // solid-angle density × selection probability; for delta lights the selection probability
  bool is_delta = false;    // point, spot, and directional lights without angular size
  std::uint32_t emitter = 0;  // emitter id (materials first, then Scene::lights)
  float scale = 1.0f;       // multiplies the emitter's spectrum: 1/r² and spot falloff, or sun-disc radiance
  Vec3f position;           // sampled point (shadow-ray target); unused for directional lights
  Vec3f normal;             // emitter normal at the point (area lights)
  bool has_rgb = false;     // environment map: radiance is `rgb` (linear, nits, in the map's texel_space)
  Vec3f rgb;
  bool has_uv = false;      // triangle of an emitter with an emission texture: `uv` at `position`
  Vec2f uv;
};

struct LightSamplerOptions {
  // Area sampling by default: on the Cornell box the solid-angle strategies lower relMSE at
  // 64 spp by only 2.7 % but cost ~35 % more time per sample (BENCHMARKS.md "Peer").
  TriangleLightSampling triangle = TriangleLightSampling::area;
  // Choose the emitter with u_point.x and reuse the rest of that number, rescaled to
  // [0,1), as u_point.x on the emitter (pbrt-v3's "sample reuse"), so a stratified u_point
  // stays stratified on every emitter (a quad light's two triangles each get a net of
  // points instead of a random half of one). Only emitters chosen with probability ≥
  // kMinReusedSelectionPmf reuse it (the remainder keeps ≥ 16 of a float's 24 bits);
  // others take u_select as their u_point.x — equally uniform, only unstratified.
  bool reuse_selection_sample = true;

  bool operator==(const LightSamplerOptions&) const = default;
};

class LightSampler {
 public:
  static constexpr float kMinReusedSelectionPmf = 1.0f / 256.0f;

  LightSampler(const Scene& scene, const Bounds3f& world_bounds, const LightSamplerOptions& options = {});

  bool empty() const { return selection_pmf_.empty(); }
  std::size_t light_count() const { return selection_pmf_.size(); }

  // u_select picks the emitter, u_point the point or direction on it. Returns nothing when
  // the chosen emitter cannot light the reference point (it faces away, zero area).
  // `receiver_normal` (unit; zero when there is none) steers triangle samples towards
  // the receiver's cosine; pdf_triangle must be given the same one.
  std::optional<LightSample> sample(const Vec3f& reference, float u_select, Vec2f u_point,
                                    const Vec3f& receiver_normal = Vec3f(0.0f)) const;
  // sample() in two halves, for a caller that samples some emitters itself (the
  // integrator's lanes, render/wavefront_plain_lanes.cpp): select() picks the emitter as
  // sample() does, with its selection probability and u_point as that emitter's own sample
  // reads it, or nothing where sample() gives nothing before asking an emitter;
  // sample_selected() is the rest of sample(), the same bits.
  struct Selection {
    std::size_t emitter_index;  // the sampler's own numbering
    float pmf;
    Vec2f u_point;
  };
  std::optional<Selection> select(float u_select, Vec2f u_point) const;
  std::optional<LightSample> sample_selected(const Selection& chosen, const Vec3f& reference,
                                             const Vec3f& receiver_normal) const;
  // The selected emitter where sample_selected() would sample it with
  // sample_triangle_light_by_area (an untextured triangle, with the area strategy): its
  // triangle, and its emitter id in `emitter`, for LightSample::emitter; null otherwise.
  // Such a sample has LightSample's defaults but for position, normal (the triangle's),
  // wi, distance, pdf (pdf_sr × the selection's pmf) and emitter.
  const TriangleLight* area_sampled_triangle(std::size_t emitter_index, std::uint32_t& emitter) const;
  // Whether sample() can read u_select at all: false when the selection number is reused
  // (options) and every emitter is chosen with probability ≥ kMinReusedSelectionPmf; the
  // caller may then skip drawing it.
  bool uses_selection_number() const { return uses_selection_number_; }

  // Density (solid angle at `reference`, including selection) with which sample() would
  // choose the point `position` on the given emissive triangle; 0 for non-emitters and
  // where its emitting side faces away from the reference.
  float pdf_triangle(std::uint32_t mesh, std::uint32_t triangle, const Vec3f& reference, const Vec3f& position,
                     const Vec3f& receiver_normal = Vec3f(0.0f)) const;

  const LightSamplerOptions& options() const { return options_; }

  // Directional lights with an angular size are hit by escaping rays: their radiance scale
  // (for the emitter's spectrum) and the density sample() gives the direction `wi`.
  struct EscapedHit {
    std::uint32_t emitter;
    float scale;
    float pdf;
    bool has_rgb = false;  // environment maps: texel radiance, see LightSample
    Vec3f rgb;
  };
  // Calls visit(const EscapedHit&) for each emitter a ray leaving the scene in direction wi
  // hits; nothing is allocated (the integrator calls this for every escaping ray).
  template <class Visit>
  void visit_escaped(const Vec3f& wi, Visit&& visit) const {
    for (const std::uint32_t i : escapable_emitters_)
      if (const std::optional<EscapedHit> hit = escaped_hit(i, wi)) visit(*hit);
  }
  std::vector<EscapedHit> escaped(const Vec3f& wi) const;  // the same hits, collected

 private:
  enum class Kind : std::uint8_t { triangle, point, spot, directional, environment };
  struct Emitter {
    Kind kind;
    std::uint32_t emitter;  // emitter id
    TriangleLight triangle;
    bool textured = false;  // uv0 + duv1·b1 + duv2·b2 at barycentrics b
    Vec2f uv0, duv1, duv2;
    // point / spot / directional
    Vec3f position, axis;
    float cos_inner = 1.0f, cos_outer = 0.0f;
    float cos_max = 1.0f;          // directional: cosine of the angular radius (1 = delta)
    float disc_radiance_scale = 1.0f;  // directional with size: L = E / (π sin²θ)
    // environment: texture (null: constant) in `mapping`, world ↔ map linear maps
    const TextureImage* texture = nullptr;
    EnvironmentMapping mapping = EnvironmentMapping::equirectangular;
    Transform world_to_map, map_to_world;
    float intensity_nits = 0.0f;
  };
  std::optional<EscapedHit> escaped_hit(std::uint32_t index, const Vec3f& wi) const;  // index into emitters_
  double build_environment_distribution(const Emitter& e);  // returns the sky's average luminance
  bool environment_built_ = false;
  // Environment radiance (linear Rec.709, nits) at the map's texel coordinates of a
  // direction (escaped rays find them once for both; light samples have them from the
  // distribution), and the solid-angle pdf of sampling that direction.
  static Vec3f environment_rgb_at(const Emitter& e, Vec2f uv);
  float environment_pdf_at(EnvironmentMapping mapping, Vec2f uv) const;
  static Vec3f map_direction(const Emitter& e, const Vec3f& world_direction);  // unit, in the map's frame
  PiecewiseConstant2D environment_distribution_;
  // The sample on emitter `index`, its pdf times the selection probability.
  std::optional<LightSample> sample_emitter(std::size_t index, const Vec3f& reference, Vec2f u,
                                           const Vec3f& receiver_normal, float selection_pmf) const;
  // Fills `s` (default-constructed) for emitter `index`; false when it cannot light the point.
  bool fill_emitter_sample(std::size_t index, const Vec3f& reference, Vec2f u, const Vec3f& receiver_normal,
                           LightSample& s) const;

  LightSamplerOptions options_;

  std::vector<Emitter> emitters_;
  std::vector<float> selection_pmf_;
  std::vector<float> selection_cdf_;
  std::vector<std::int64_t> first_triangle_of_mesh_;  // -1 for meshes without emission
  // What a ray leaving the scene can hit: the environment and directional lights with a
  // size. escaped() visits only these, not every emissive triangle.
  std::vector<std::uint32_t> escapable_emitters_;
  bool uses_selection_number_ = true;
};

// Inline: the integrator's lanes call these once per light sample
// (render/wavefront_plain_lanes.cpp).
inline std::optional<LightSampler::Selection> LightSampler::select(float u_select, Vec2f u_point) const {
  if (empty()) return std::nullopt;
  const float u_choice = options_.reuse_selection_sample ? u_point.x : u_select;
  // Which light is a coin flip per sample among lights of like power: the search without
  // branches (core/branch_free.h).
  const std::size_t index =
      std::min(upper_bound_index(selection_cdf_.data(), selection_cdf_.size(), u_choice), selection_cdf_.size() - 1);
  const float pmf = selection_pmf_[index];
  if (pmf == 0.0f) return std::nullopt;  // float ties at the top of the CDF
  if (options_.reuse_selection_sample) {
    // u_point.x ∈ [cdf_before, cdf_before + pmf): uniform there, so its position in that
    // interval is a uniform number, stratified as u_point.x was.
    const float cdf_before = keep_if(index != 0, selection_cdf_[index - (index != 0)]);
    u_point.x = pmf >= kMinReusedSelectionPmf
                    ? std::clamp((u_point.x - cdf_before) / pmf, 0.0f, 0x1.fffffep-1f)
                    : u_select;
  }
  return Selection{index, pmf, u_point};
}

inline const TriangleLight* LightSampler::area_sampled_triangle(std::size_t emitter_index, std::uint32_t& emitter) const {
  const Emitter& e = emitters_[emitter_index];
  if (e.kind != Kind::triangle || e.textured || options_.triangle != TriangleLightSampling::area) return nullptr;
  emitter = e.emitter;
  return &e.triangle;
}

}  // namespace prism
