// Hits on plain diffuse materials shaded lanes::kWidth at a time: the steps shade() takes
// for such a hit (surface_interaction, then shade_surface<true>), in the same order, with
// the arithmetic on directions and points done for all the lanes at once (core/float_lanes.h)
// and the spectra, the light sampler and the emitters' spectra lane by lane. Every float is
// the scalar step's own operation on the same operands, so each slot ends with the bits
// shade() gives it (plain_diffuse_render_test compares whole images); the hits that cannot
// go this way (WavefrontIntegrator::shades_in_lanes) are shaded alone.
//
// Why: on the Cornell box the plain path spends most of its instructions on three-vector
// arithmetic in scalar registers (the hit's geometry, its frame, the light sample's and the
// sampled direction's coordinates, the rays' offsets), which here costs a quarter as many
// instructions (BENCHMARKS.md "Session 33").
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "prism/core/float_lanes.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/render/wavefront_paths.h"
#include "prism/sampling/warps.h"
#include "prism/scene/triangle_light_sampling.h"

namespace prism {
namespace {

using lanes::Float;
using lanes::Mask;
constexpr int kLanes = lanes::kWidth;
static_assert(kLanes == 4, "the gathers below name four lanes");

// A vector of the four lanes' values.
template <class Value>
Float gather(const Value& value) {
  return Float{value(0), value(1), value(2), value(3)};
}
template <class Value>
Mask gather_mask(const Value& on) {
  return Mask{on(0) ? -1 : 0, on(1) ? -1 : 0, on(2) ? -1 : 0, on(3) ? -1 : 0};
}
lanes::Vec3 gather(const std::array<const Vec3f*, kLanes>& v) {
  return {Float{v[0]->x, v[1]->x, v[2]->x, v[3]->x}, Float{v[0]->y, v[1]->y, v[2]->y, v[3]->y},
          Float{v[0]->z, v[1]->z, v[2]->z, v[3]->z}};
}
Vec3f lane(const lanes::Vec3& v, int k) { return {v.x[k], v.y[k], v.z[k]}; }

// Frame::from_normal, to_local and to_world (core/frame.h) in lanes.
struct FrameLanes {
  lanes::Vec3 s, t, n;
  static FrameLanes from_normal(const lanes::Vec3& n) {
    const Float sign = lanes::copysign_one(n.z);
    const Float a = -1.0f / (sign + n.z);
    const Float b = n.x * n.y * a;
    return {{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
  }
  lanes::Vec3 to_local(const lanes::Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  lanes::Vec3 to_world(const lanes::Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

// offset_ray_origin (surface_interaction.h) in lanes.
lanes::Vec3 offset_ray_origin(const lanes::Vec3& p, const lanes::Vec3& n, const lanes::Vec3& direction) {
  const Float magnitude = lanes::max(lanes::max(lanes::abs(p.x), lanes::abs(p.y)),
                                     lanes::max(lanes::abs(p.z), lanes::splat(1.0f)));
  return p + lanes::select(dot(direction, n) >= 0.0f, n, -n) * (magnitude * 1e-5f);
}

// Lambertian::pdf (bsdf/lambertian.h): cosine_hemisphere_pdf of |cos θi| where wo and wi
// lie on one side (same_hemisphere), 0 elsewhere.
Float lambertian_pdf(Float wo_z, Float wi_z) {
  const Float abs_cos = lanes::abs(wi_z);
  const Float cosine_pdf = lanes::select(abs_cos > 0.0f, abs_cos * std::numbers::inv_pi_v<float>, lanes::splat(0.0f));
  return lanes::select(wo_z * wi_z > 0.0f, cosine_pdf, lanes::splat(0.0f));
}

}  // namespace

template <class Mode>
void WavefrontIntegrator<Mode>::shade_plain_lanes(Paths& p, const std::uint32_t* slots) const {
  static constexpr Vec3f kNoNormal{};  // for flat meshes: interpolates to 0, so ns = ng as below
  std::array<const Vec3f*, kLanes> v0, v1, v2, n0, n1, n2;
  std::array<std::uint32_t, kLanes> material;
  for (int k = 0; k < kLanes; ++k) {
    const std::uint32_t s = slots[k];
    p.shadow_pending[s] = 0;
    const Hit& hit = p.hit[s];
    const TriangleMesh& mesh = scene_.meshes[hit.mesh];
    const std::uint32_t* index = mesh.indices.data() + 3 * static_cast<std::size_t>(hit.triangle);
    v0[k] = &mesh.positions[index[0]];
    v1[k] = &mesh.positions[index[1]];
    v2[k] = &mesh.positions[index[2]];
    const bool smooth = !mesh.normals.empty();
    n0[k] = smooth ? &mesh.normals[index[0]] : &kNoNormal;
    n1[k] = smooth ? &mesh.normals[index[1]] : &kNoNormal;
    n2[k] = smooth ? &mesh.normals[index[2]] : &kNoNormal;
    material[k] = mesh.material;
    p.cone_width[s] += p.cone_spread[s] * hit.t;  // the ray cone's width at this hit
  }

  // surface_interaction: the position from barycentrics, the unit front-face normal, the
  // interpolated shading normal turned to its side (ng where the mesh has none, or it is 0).
  const Float u = gather([&](int k) { return p.hit[slots[k]].u; });
  const Float v = gather([&](int k) { return p.hit[slots[k]].v; });
  const lanes::Vec3 direction{gather([&](int k) { return p.ray[slots[k]].direction.x; }),
                              gather([&](int k) { return p.ray[slots[k]].direction.y; }),
                              gather([&](int k) { return p.ray[slots[k]].direction.z; })};
  const lanes::Vec3 p0 = gather(v0), p1 = gather(v1), p2 = gather(v2);
  const Float b0 = 1.0f - u - v;
  const lanes::Vec3 position = p0 * b0 + p1 * u + p2 * v;
  const lanes::Vec3 cross_p = cross(p1 - p0, p2 - p0);
  const Float world_area = 0.5f * length(cross_p);
  const lanes::Vec3 ng = cross_p * (1.0f / (2.0f * world_area));
  const lanes::Vec3 n = gather(n0) * b0 + gather(n1) * u + gather(n2) * v;
  const Float n_length = length(n);
  lanes::Vec3 ns = n * (1.0f / n_length);
  ns = lanes::select(dot(ns, ng) < 0.0f, -ns, ns);
  ns = lanes::select(n_length > 0.0f, ns, ng);
  const FrameLanes shading = FrameLanes::from_normal(ns);
  const lanes::Vec3 wo = shading.to_local(-direction);

  // Lane by lane: the base colour, the bounce's numbers and the light sampler's choice of
  // emitter. An untextured triangle sampled by area is sampled below, in lanes; any other
  // emitter by the sampler (LightSampler::select, area_sampled_triangle, sample_selected).
  std::array<Spectrum<Mode>, kLanes> reflectance;  // the bare Lambertian lobe's R (PlainDiffuseBsdf)
  std::array<BounceSamples, kLanes> numbers;
  std::array<const TriangleLight*, kLanes> light_triangle{};  // lanes sampled here
  std::array<LightSampler::Selection, kLanes> selection{};
  std::array<std::uint32_t, kLanes> light_emitter{};
  std::array<std::optional<LightSample>, kLanes> light;  // lanes the sampler sampled
  bool sampler_sampled = false;
  for (int k = 0; k < kLanes; ++k) {
    const std::uint32_t s = slots[k];
    reflectance[k] = colors_.base_color(material[k], p.wavelengths[s]);
    unsigned needs = kNeedDirection;
    if (use_nee_) needs |= lights_.uses_selection_number() ? kNeedLight : kNeedLightPoint;
    if (p.depth[s] + 1 >= settings_.russian_roulette_depth) needs |= kNeedRoulette;
    numbers[k] = bounce_blocks_ahead_ ? only_needed(p.bounce_block[s], needs)
                                      : bounce_samples(settings_.sampler, pixel_sample(p, s), p.depth[s], needs);
    if (!use_nee_) continue;
    const std::optional<LightSampler::Selection> chosen = lights_.select(numbers[k].light_select, numbers[k].light);
    if (!chosen) continue;
    selection[k] = *chosen;
    light_triangle[k] = lights_.area_sampled_triangle(chosen->emitter_index, light_emitter[k]);
    if (light_triangle[k]) continue;
    light[k] = lights_.sample_selected(*chosen, lane(position, k), lane(shading.n, k));
    sampler_sampled = true;
  }

  if (use_nee_) {
    // sample_triangle_light_by_area (scene/triangle_light_sampling.h), the pdf times the
    // selection's pmf as LightSampler::sample_emitter.
    static const TriangleLight kNoTriangle;  // area 0: draws nothing
    static const LightSample kNoLight;        // and LightSample's defaults
    const auto triangle = [&](int k) -> const TriangleLight& {
      return light_triangle[k] ? *light_triangle[k] : kNoTriangle;
    };
    const lanes::Vec3 t0{gather([&](int k) { return triangle(k).p0.x; }), gather([&](int k) { return triangle(k).p0.y; }),
                         gather([&](int k) { return triangle(k).p0.z; })};
    const lanes::Vec3 t1{gather([&](int k) { return triangle(k).e1.x; }), gather([&](int k) { return triangle(k).e1.y; }),
                         gather([&](int k) { return triangle(k).e1.z; })};
    const lanes::Vec3 t2{gather([&](int k) { return triangle(k).e2.x; }), gather([&](int k) { return triangle(k).e2.y; }),
                         gather([&](int k) { return triangle(k).e2.z; })};
    lanes::Vec3 light_normal{gather([&](int k) { return triangle(k).normal.x; }),
                             gather([&](int k) { return triangle(k).normal.y; }),
                             gather([&](int k) { return triangle(k).normal.z; })};
    const Float area = gather([&](int k) { return triangle(k).area; });
    const Mask two_sided = gather_mask([&](int k) { return triangle(k).two_sided; });
    const Float pmf = gather([&](int k) { return selection[k].pmf; });
    const Float point_x = gather([&](int k) { return selection[k].u_point.x; });
    const Float point_y = gather([&](int k) { return selection[k].u_point.y; });
    const Float half = 0.5f * lanes::min(point_x, point_y);  // sample_uniform_triangle (warps.h)
    lanes::Vec3 light_position = t0 + t1 * (point_x - half) + t2 * (point_y - half);
    const lanes::Vec3 to_light = light_position - position;
    const Float d2 = dot(to_light, to_light);
    Float distance = lanes::sqrt(d2);
    lanes::Vec3 wi = to_light * (1.0f / distance);
    const Float facing = -dot(light_normal, wi);
    const Float cos_light = lanes::select(two_sided, lanes::abs(facing), facing);
    Float light_pdf = d2 / (cos_light * area) * pmf;
    Mask drawn = (area > 0.0f) & (d2 > 0.0f) & ~(cos_light <= 0.0f);
    Mask delta = lanes::all_lanes(false);
    if (sampler_sampled) {
      // The lanes the sampler sampled, from its LightSamples.
      const auto sample = [&](int k) -> const LightSample& { return light[k] ? *light[k] : kNoLight; };
      const Mask by_sampler = gather_mask([&](int k) { return light[k].has_value(); });
      const auto take = [&](Float& mine, Float theirs) { mine = lanes::select(by_sampler, theirs, mine); };
      take(wi.x, gather([&](int k) { return sample(k).wi.x; }));
      take(wi.y, gather([&](int k) { return sample(k).wi.y; }));
      take(wi.z, gather([&](int k) { return sample(k).wi.z; }));
      take(light_pdf, gather([&](int k) { return sample(k).pdf; }));
      take(distance, gather([&](int k) { return sample(k).distance; }));
      take(light_position.x, gather([&](int k) { return sample(k).position.x; }));
      take(light_position.y, gather([&](int k) { return sample(k).position.y; }));
      take(light_position.z, gather([&](int k) { return sample(k).position.z; }));
      take(light_normal.x, gather([&](int k) { return sample(k).normal.x; }));
      take(light_normal.y, gather([&](int k) { return sample(k).normal.y; }));
      take(light_normal.z, gather([&](int k) { return sample(k).normal.z; }));
      delta = gather_mask([&](int k) { return sample(k).is_delta; });
      drawn |= by_sampler;  // their triangle is kNoTriangle, drawn nowhere above
    }

    // The light sample's direction on both sides, its MIS weight, and the shadow ray.
    const lanes::Vec3 wi_local = shading.to_local(wi);
    // The geometric and the shading side must agree, or light leaks through edges.
    const Mask lit = drawn & ((dot(wi, ng) > 0.0f) == (wi_local.z > 0.0f)) & (light_pdf > 0.0f);
    const Mask same_side = wo.z * wi_local.z > 0.0f;  // Lambertian::eval is 0 elsewhere
    const Float bsdf_pdf = lambertian_pdf(wo.z, wi_local.z);
    const Float a2 = light_pdf * light_pdf, b2 = bsdf_pdf * bsdf_pdf;  // power_heuristic (warps.h)
    const Float heuristic = lanes::select(a2 + b2 > 0.0f, a2 / (a2 + b2), lanes::splat(0.0f));
    const Float w = lanes::select(~delta & lanes::all_lanes(weight_bsdf_hits_), heuristic, lanes::splat(1.0f));
    const lanes::Vec3 origin = offset_ray_origin(position, ng, wi);
    const lanes::Vec3 target =
        lanes::select(delta, light_position, offset_ray_origin(light_position, light_normal, -wi));
    const lanes::Vec3 segment = target - origin;
    const Float segment_length = length(segment);
    const Mask far = lanes::is_inf(distance);
    const lanes::Vec3 shadow_direction = lanes::select(far, wi, segment * (1.0f / segment_length));
    const Float t_max = lanes::select(far, lanes::splat(std::numeric_limits<float>::infinity()),
                                      segment_length * (1.0f - 1e-4f));
    const Float weight = lanes::abs(wi_local.z) * w / light_pdf;
    for (int k = 0; k < kLanes; ++k) {
      if (!lit[k]) continue;
      const Spectrum<Mode> f = same_side[k] ? reflectance[k] * std::numbers::inv_pi_v<float> : Spectrum<Mode>{};
      if (f.is_black()) continue;
      const std::uint32_t s = slots[k];
      const Wavelengths<Mode>& wl = p.wavelengths[s];
      p.shadow_ray[s] = Ray{lane(origin, k), lane(shadow_direction, k), 0.0f, t_max[k]};
      // A triangle sampled here has LightSample's defaults: no rgb, no uv, scale 1.
      const LightSample& ls = light[k] ? *light[k] : kNoLight;
      const Spectrum<Mode> Le =
          ls.has_rgb ? colors_.environment_radiance(ls.rgb, wl)
                     : (ls.has_uv ? textured_emitted_radiance(ls.emitter, ls.uv, 0.0f, wl)
                                  : untextured_emission(p, s, light[k] ? ls.emitter : light_emitter[k])) *
                           ls.scale;
      p.shadow_contribution[s] = p.throughput[s] * f * Le * weight[k];
      p.shadow_pending[s] = 1;
    }
  }

  // Lambertian::sample: sample_cosine_hemisphere (warps.h) on wo's side, and its pdf.
  const Float a = 2.0f * gather([&](int k) { return numbers[k].direction.x; }) - 1.0f;
  const Float b = 2.0f * gather([&](int k) { return numbers[k].direction.y; }) - 1.0f;
  const Float abs_a = lanes::abs(a), abs_b = lanes::abs(b);
  const Mask wedge = abs_b < abs_a;
  const Float r = lanes::select(wedge, a, b);
  const CosSinOf<Float> cs = cos_sin_quarter_pi(lanes::select(wedge, b, a) / r);
  const Float along = r * cs.cos, across = r * cs.sin;
  const Mask centre = (a == 0.0f) & (b == 0.0f);
  const Float disk_x = lanes::select(centre, lanes::splat(0.0f), lanes::select(wedge, along, across));
  const Float disk_y = lanes::select(centre, lanes::splat(0.0f), lanes::select(wedge, across, along));
  const Float disk_z = lanes::sqrt(lanes::max(lanes::splat(0.0f), 1.0f - disk_x * disk_x - disk_y * disk_y));
  const lanes::Vec3 wi_sampled{disk_x, disk_y, lanes::select(wo.z < 0.0f, -disk_z, disk_z)};
  const Float pdf = lambertian_pdf(wo.z, wi_sampled.z);
  // Kept: a sample (wo off the surface, pdf ≠ 0) whose pdf is not ≤ 0, as shade_surface asks.
  const Mask kept = (wo.z != 0.0f) & (pdf != 0.0f) & ~(pdf <= 0.0f);
  const lanes::Vec3 wi_world = shading.to_world(wi_sampled);
  // A direction on the other geometric side than its shading side says would pass through
  // the mesh.
  const Mask through = (dot(wi_world, ng) > 0.0f) != (wi_sampled.z > 0.0f);
  const Float cosine_over_pdf = lanes::abs(wi_sampled.z) / pdf;
  const lanes::Vec3 next_origin = offset_ray_origin(position, ng, wi_world);

  for (int k = 0; k < kLanes; ++k) {
    const std::uint32_t s = slots[k];
    // Where the sample is kept it lies on wo's side, so f = R/π (Lambertian::eval).
    const Spectrum<Mode> f = reflectance[k] * std::numbers::inv_pi_v<float>;
    if (!kept[k] || f.is_black() || through[k]) {
      p.finished[s] = 1;
      continue;
    }
    Spectrum<Mode>& beta = p.throughput[s];
    beta *= f * cosine_over_pdf[k];
    // A reflection: η = 1 leaves eta_scale as it is, and the path stays outside media.
    p.prev_pdf[s] = pdf[k];
    p.prev_specular[s] = 0;
    p.cone_spread[s] = std::max(p.cone_spread[s], 0.05f);
    p.prev_position[s] = lane(position, k);
    p.prev_normal[s] = lane(shading.n, k);
    p.depth[s] += 1;
    // Russian roulette, as shade_surface.
    if (p.depth[s] >= settings_.russian_roulette_depth) {
      float max_beta = 0.0f;
      for (int i = 0; i < Mode::kChannels; ++i) max_beta = std::max(max_beta, beta[i]);
      const float survive = std::min(1.0f, max_beta * p.eta_scale[s]);
      if (numbers[k].roulette >= survive) {
        p.finished[s] = 1;
        continue;
      }
      beta *= 1.0f / survive;
    }
    p.ray[s] = Ray{lane(next_origin, k), lane(wi_world, k)};
  }
}

template void WavefrontIntegrator<SpectralMode<3>>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<SpectralMode<4>>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<SpectralMode<8>>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<RgbMode>::shade_plain_lanes(Paths&, const std::uint32_t*) const;

}  // namespace prism
