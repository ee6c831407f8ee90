#include "prism/render/wavefront_integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "prism/bsdf/plain_diffuse_bsdf.h"
#include "prism/core/branch_free.h"
#include "prism/core/float_lanes.h"
#include "prism/core/frame.h"
#include "prism/core/parallel.h"
#include "prism/render/anisotropy.h"
#include "prism/render/bump_mapping.h"
#include "prism/render/material_bsdf.h"
#include "prism/render/normal_mapping.h"
#include "prism/render/surface_interaction.h"
#include "prism/render/volume_absorption.h"
#include "prism/render/wavefront_paths.h"
#include "prism/sampling/padded_sobol.h"
#include "prism/sampling/padded_sobol_lanes.h"
#include "prism/scene/emission.h"
#include "prism/sampling/warps.h"

namespace prism {

template <class Mode>
WavefrontIntegrator<Mode>::WavefrontIntegrator(const Scene& scene, const EmbreeAccel& accel,
                                               const std::vector<MipPyramid>& mip_pyramids, const LightSampler& lights,
                                               const PinholeCamera& camera, const ColorContext<Mode>& colors,
                                               const PathSettings& settings, int width, int height, std::uint64_t seed,
                                               bool regenerate)
    : shading_(scene, mip_pyramids, colors, settings.normal_mapping), scene_(scene), accel_(accel), lights_(lights),
      camera_(camera), colors_(colors), settings_(settings), width_(width), height_(height), seed_(seed),
      regenerate_(regenerate) {
  // Geometry that fits a core's L2 cache (≥ 512 KiB on current x86) is left to the hardware.
  std::size_t geometry_bytes = 0;
  for (const TriangleMesh& m : scene.meshes)
    geometry_bytes += m.indices.size() * sizeof(std::uint32_t) +
                      (m.positions.size() + m.normals.size() + m.tangents.size()) * sizeof(Vec3f) +
                      m.uvs.size() * sizeof(Vec2f);
  prefetch_geometry_ = geometry_bytes > (std::size_t{512} << 10);
  // Cheap only on the padded Sobol' lanes, which the shading loop then calls directly,
  // without bounce_samples' dispatch.
  sampler_lanes_ = sampler_lanes(settings_.simd);
  sobol_lanes_ = whole_bounce_blocks_are_cheap(settings_.sampler, sampler_lanes_);
  use_nee_ = settings_.estimator != LightEstimator::bsdf_only && !lights_.empty();
  weight_bsdf_hits_ = settings_.estimator == LightEstimator::mis;
  for (const Material& m : scene.materials) plain_diffuse_.push_back(is_plain_diffuse(m) ? 1 : 0);
  require_simd_level(settings_.simd);
  lane_width_ = shading_lane_width(settings_.simd);
#if PRISM_FLOAT_LANES_AVX2
  static_assert(lanes::avx2::kWidth <= kMaxLaneWidth);
#endif
  static_assert(lanes::sse2::kWidth <= kMaxLaneWidth);
  for (const TriangleMesh& mesh : scene.meshes) {
    const bool plain = mesh.material < scene.materials.size() && plain_diffuse_[mesh.material] &&
                       !scene.materials[mesh.material].is_emissive();
    lane_mesh_.push_back(lane_width_ > 0 && plain && mesh.tangents.empty() ? 1 : 0);
  }
  if (lane_mesh_.empty()) lane_mesh_.push_back(0);  // shades_in_lanes reads entry 0 for misses
}

template <class Mode>
WavefrontIntegrator<Mode>::~WavefrontIntegrator() = default;

template <class Mode>
PixelSample WavefrontIntegrator<Mode>::pixel_sample(const Paths& p, std::uint32_t slot) const {
  return {seed_, p.first_pixel + slot, static_cast<std::uint32_t>(width_), p.sample_index[slot]};
}

template <class Mode>
Vec2f WavefrontIntegrator<Mode>::facet_numbers(const Paths& p, std::uint32_t slot) const {
  return sample_2d(settings_.sampler, pixel_sample(p, slot),
                   kFirstFacetDimension + 2 * static_cast<std::uint32_t>(p.depth[slot]));
}

namespace {

// Holds a block's lock where the path state has them (the whole-image queue, whose
// threads start paths of the same block at once); nothing otherwise.
class BlockLock {
 public:
  explicit BlockLock(std::atomic<std::uint8_t>* lock) : lock_(lock) {
    if (!lock_) return;
    while (lock_->exchange(1, std::memory_order_acquire) != 0)
      while (lock_->load(std::memory_order_relaxed) != 0) std::this_thread::yield();
  }
  ~BlockLock() {
    if (lock_) lock_->store(0, std::memory_order_release);
  }
  BlockLock(const BlockLock&) = delete;
  BlockLock& operator=(const BlockLock&) = delete;

 private:
  std::atomic<std::uint8_t>* lock_;
};

}  // namespace

template <class Mode>
std::size_t WavefrontIntegrator<Mode>::trace_camera_packet(Paths& p, std::size_t block, std::uint32_t sample,
                                                           std::uint32_t slot, PacketNumbers& u) const {
  constexpr std::size_t kLanes = CameraPacketCache::kLanes;
  const auto width = static_cast<std::uint32_t>(width_);
  const std::uint64_t pixels = std::uint64_t{width} * static_cast<std::uint32_t>(height_);
  const auto first_slot = static_cast<std::uint32_t>(block * kLanes);
  // The lanes are the block's pixels inside the image, whichever of them need the packet
  // now: the packet is always the same. It waits for the other lanes that have not
  // reached this sample, and will.
  unsigned count = 0;  // the lanes are a prefix: the first `count`
  std::uint8_t waiting = 0;
  for (std::uint32_t i = 0; i < kLanes; ++i) {
    const std::uint32_t s = first_slot + i;
    if (s >= p.capacity() || p.first_pixel + std::uint64_t{s} >= pixels) break;
    ++count;
    if (s != slot && p.camera_next_sample[s] <= sample && sample < p.sample_end[s]) waiting |= std::uint8_t(1u << i);
  }
  const std::size_t at = p.camera_packets.claim(block, sample, waiting);
  CameraPacketCache::Packet& packet = p.camera_packets.packet(at);
  const bool lens = camera_.has_lens();
  if (sobol_lanes_) {
    std::array<CameraBlockRequest, kLanes> requests;
    for (std::uint32_t i = 0; i < count; ++i)
      requests[i] = {p.sobol_pixel_key[first_slot + i], sample, u.data() + i};  // set_up made every lane's
    padded_sobol_camera_blocks_lanes(sampler_lanes_, {requests.data(), count}, lens);
  } else {
    for (std::uint32_t i = 0; i < count; ++i)
      u.set(i, camera_samples(settings_.sampler, sampler_lanes_,
                              PixelSample{seed_, p.first_pixel + first_slot + i, width, sample}, lens));
  }
  LaneSlots<Ray, kLanes> rays;  // every lane written, nothing cleared first (core/lane_slots.h)
  for (std::uint32_t i = 0; i < kLanes; ++i) {
    const std::uint32_t lane = i < count ? i : 0;  // unused lanes: a copy of lane 0
    const std::uint32_t pixel = p.first_pixel + first_slot + lane;
    // Stored a float at a time, as the store buffer can forward (core/ray.h).
    store_ray(rays.data()[i],
              camera_.generate_ray(static_cast<float>(pixel % width) + u[lane].pixel_jitter.x,
                                   static_cast<float>(pixel / width) + u[lane].pixel_jitter.y, u[lane].lens));
  }
  LaneSlots<Hit, kLanes> hits;
  std::array<std::uint8_t, kLanes> found;
  const unsigned lanes = (1u << count) - 1u;
  accel_.intersect_packet(rays.data(), lanes, hits.data(), found.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    CameraPacketCache::Lane& lane = packet.lanes[i];
    store_ray(lane.ray, rays[i]);
    lane.hit = hits[i];
    lane.found = found[i];
    lane.wavelength = u[i].wavelength;
  }
  if (p.block_locks)
    p.camera_packet_rays.fetch_add(count, std::memory_order_relaxed);
  else  // one thread: no locked add
    p.camera_packet_rays.store(p.camera_packet_rays.load(std::memory_order_relaxed) + count, std::memory_order_relaxed);
  return at;
}

template <class Mode>
void WavefrontIntegrator<Mode>::take_camera_lane(Paths& p, std::uint32_t slot, std::uint32_t sample,
                                                 double& wavelength_number, PacketNumbers& numbers) const {
  const std::size_t block = slot / CameraPacketCache::kLanes;
  const BlockLock lock(p.block_locks ? &p.block_locks[block] : nullptr);
  const std::ptrdiff_t held = p.camera_packets.find(block, sample);
  const std::size_t at =
      held >= 0 ? static_cast<std::size_t>(held) : trace_camera_packet(p, block, sample, slot, numbers);
  const CameraPacketCache::Lane& lane = p.camera_packets.packet(at).lanes[slot % CameraPacketCache::kLanes];
  store_ray(p.ray[slot], lane.ray);
  p.hit[slot] = lane.hit;
  p.hit_found[slot] = static_cast<std::uint8_t>(lane.found);
  wavelength_number = lane.wavelength;
  p.camera_packets.take(at, slot % CameraPacketCache::kLanes);
  p.camera_next_sample[slot] = sample + 1;
}

template <class Mode>
void WavefrontIntegrator<Mode>::generate(Paths& p, const std::uint32_t* slots, const std::uint32_t* sample_indices,
                                         std::size_t count) const {
  // In runs of kGenerateRun slots, one stage at a time for the whole run: the camera rays,
  // their hits and wavelength numbers (from the blocks' camera packets, traced where not
  // held), then the wavelengths (two tuples per pass on AVX2), then the path state. Each
  // slot's numbers are those it would get alone (docs/performance-design.md "Sampler blocks and
  // branch-free walks").
  constexpr std::size_t kGenerateRun = 32;
  std::array<double, kGenerateRun> wavelength_numbers;
  PacketNumbers numbers;
  for (std::size_t first = 0; first < count; first += kGenerateRun) {
    const std::size_t n = std::min(kGenerateRun, count - first);
    const std::uint32_t* run = slots + first;
    const std::uint32_t* run_samples = sample_indices + first;
    // The lanes of packets traced steps ago are seldom in the caches any more: fetched
    // for the whole run before the first is read (a packet traced on the way is fetched
    // by its tracing). Not in a shared path state, whose blocks are read under their locks.
    for (std::size_t k = 0; k < n && !p.block_locks; ++k) {
      const std::ptrdiff_t held = p.camera_packets.find(run[k] / CameraPacketCache::kLanes, run_samples[k]);
      if (held < 0) continue;
      const CameraPacketCache::Packet& packet = p.camera_packets.packet(static_cast<std::size_t>(held));
      __builtin_prefetch(&packet.lanes[run[k] % CameraPacketCache::kLanes]);
    }
    for (std::size_t k = 0; k < n; ++k) take_camera_lane(p, run[k], run_samples[k], wavelength_numbers[k], numbers);
    std::size_t k = 0;
    for (; k + 1 < n; k += 2)
      colors_.sample_wavelength_pair({run_samples[k], run_samples[k + 1]},
                                     {wavelength_numbers[k], wavelength_numbers[k + 1]}, p.wavelengths[run[k]],
                                     p.wavelengths[run[k + 1]]);
    if (k < n) p.wavelengths[run[k]] = colors_.sample_wavelengths(run_samples[k], wavelength_numbers[k]);
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t slot = run[k];
      p.throughput[slot] = Spectrum<Mode>(1.0f);
      p.radiance[slot] = Spectrum<Mode>(0.0f);
      p.depth[slot] = 0;
      p.prev_pdf[slot] = 0.0f;
      p.eta_scale[slot] = 1.0f;
      p.cone_width[slot] = 0.0f;
      p.cone_spread[slot] = camera_.pixel_spread_angle();
      p.prev_specular[slot] = 1;  // camera rays see emitters directly, unweighted
      p.finished[slot] = 0;
      p.inside_absorbing[slot] = 0;
      p.sample_index[slot] = run_samples[k];
      p.cached_emitter[slot] = kNoCachedEmitter;  // new wavelengths
    }
  }
}

template <class Mode>
Spectrum<Mode> WavefrontIntegrator<Mode>::untextured_emission(Paths& p, std::uint32_t slot,
                                                              std::uint32_t emitter) const {
  // An untextured emitter's spectrum is a function of the emitter and the path's
  // wavelengths alone, and a path's light samples mostly land on one emitter (every one,
  // in a scene with a single lamp): kept per path, it is evaluated about once per path
  // instead of once per light sample (Callgrind, docs/performance-design.md "Instruction cuts"). The same
  // values: a cache, not an approximation. Hero termination changes only the pdfs. RGB
  // emission is a load already.
  if constexpr (!Mode::kSpectral) return colors_.emission(emitter, p.wavelengths[slot]);
  if (p.cached_emitter[slot] != emitter) {
    p.cached_emission[slot] = colors_.emission(emitter, p.wavelengths[slot]);
    p.cached_emitter[slot] = emitter;
  }
  return p.cached_emission[slot];
}

template <class Mode>
void WavefrontIntegrator<Mode>::shade(Paths& p, std::uint32_t slot) const {
  p.shadow_pending[slot] = 0;
  Spectrum<Mode>& beta = p.throughput[slot];
  Spectrum<Mode>& L = p.radiance[slot];
  Wavelengths<Mode>& wl = p.wavelengths[slot];
  const Ray& ray = p.ray[slot];
  if (p.depth[slot] == 0 && !p.first_hit_aovs.empty())
    shading_.first_hit_aovs(p.first_hit_aovs[slot], ray, p.hit_found[slot] ? &p.hit[slot] : nullptr,
                            p.cone_spread[slot]);
  // The segment that led here ran inside an absorbing dielectric: Beer–Lambert over its
  // length (ray directions are unit vectors, so t is in scene units), before anything at
  // its end is counted.
  if (p.inside_absorbing[slot])
    beta *= beer_lambert_transmittance(p.interior_sigma[slot], p.hit_found[slot]
                                                                   ? p.hit[slot].t
                                                                   : std::numeric_limits<float>::infinity());

  if (!p.hit_found[slot]) {
    // Escaped: only the environment and directional lights with an angular size can be hit.
    lights_.visit_escaped(ray.direction, [&](const LightSampler::EscapedHit& e) {
      float w = 1.0f;
      if (!p.prev_specular[slot] && use_nee_) w = weight_bsdf_hits_ ? power_heuristic(p.prev_pdf[slot], e.pdf) : 0.0f;
      const Spectrum<Mode> Le = e.has_rgb ? colors_.environment_radiance(e.rgb, wl) : colors_.emission(e.emitter, wl) * e.scale;
      L += beta * Le * w;
    });
    p.finished[slot] = 1;
    return;
  }

  SurfaceInteraction si = surface_interaction(scene_, p.hit[slot], ray);
  if (plain_diffuse_[si.material])
    shade_surface<true>(p, slot, si);
  else
    shade_surface<false>(p, slot, si);
}

template <class Mode>
bool WavefrontIntegrator<Mode>::shades_in_lanes(const Paths& p, std::uint32_t slot) const {
  // Without branches (the stage-2 split calls it for every slot): a miss looks up mesh 0's
  // entry, which lane_mesh_ always has, and is not taken whatever it says.
  const bool found = p.hit_found[slot] != 0;
  const std::uint32_t mesh = found ? p.hit[slot].mesh : 0u;
  const std::int32_t depth = p.depth[slot];
  const auto bit = [](bool b) { return static_cast<unsigned>(b); };
  return (bit(found) & bit(lane_mesh_[mesh] != 0) & bit(p.inside_absorbing[slot] == 0) &
          bit(depth < settings_.max_depth) & (bit(depth != 0) | bit(p.first_hit_aovs.empty()))) != 0;
}

template <class Mode>
template <bool kPlainDiffuse>
void WavefrontIntegrator<Mode>::shade_surface(Paths& p, std::uint32_t slot, SurfaceInteraction& si) const {
  Wavelengths<Mode>& wl = p.wavelengths[slot];
  const Ray& ray = p.ray[slot];
  const Material& material = scene_.materials[si.material];
  p.cone_width[slot] += p.cone_spread[slot] * p.hit[slot].t;  // the ray cone's width at this hit
  MappedFrame mapped{si.shading, std::nullopt, std::nullopt};
  if constexpr (!kPlainDiffuse) mapped = shading_.map_frame(material, si, p.cone_width[slot], ray);
  if (SurfaceShading<Mode>::emits_toward(material, si)) add_surface_emission<kPlainDiffuse>(p, slot, si);
  if (p.depth[slot] + 1 > settings_.max_depth) {
    p.finished[slot] = 1;
    return;
  }

  // A clear-coat normal map's frame, which the coat points at: lives as long as the BSDF.
  std::optional<Frame> own_coat_frame;
  using PlainBsdf = bsdf::PlainDiffuseBsdf<Mode::kChannels>;
  auto bsdf = [&] {
    // A plain diffuse material's BSDF is make_bsdf's bare Lambertian lobe of its untextured
    // base colour.
    if constexpr (kPlainDiffuse) {
      return PlainBsdf{{colors_.base_color(si.material, wl)}};
    } else {
      return shading_.bsdf(material, si, p.cone_width[slot], ray, wl, mapped, own_coat_frame);
    }
  }();
  if constexpr (Mode::kSpectral) {
    // Hero wavelength after a dispersive event (Wilkie et al. 2014): from here on only
    // channel 0 carries an estimate; terminate once (pdf[1] = 0 marks it done).
    if (Mode::kChannels > 1 && bsdf.is_dispersive() && wl.pdf[1] != 0.0f) colors_.terminate_secondary(wl);
  }
  const Vec3f wo_local = si.shading.to_local(-ray.direction);
  // The bounce's block of dimensions stays reserved whole, so dimensions stay aligned, but
  // only the numbers this vertex reads are drawn (the others cost a hash each).
  const bool light_sampled = use_nee_ && !bsdf.is_specular();
  unsigned needs = 0;
  if (light_sampled) needs |= lights_.uses_selection_number() ? kNeedLight : kNeedLightPoint;
  if (bsdf.uses_lobe_sample()) needs |= kNeedLobe;
  if (bsdf.uses_direction_sample()) needs |= kNeedDirection;
  if (p.depth[slot] + 1 >= settings_.russian_roulette_depth) needs |= kNeedRoulette;
  const BounceSamples u = bounce_numbers(p, slot, needs);
  if (light_sampled) queue_shadow_ray<kPlainDiffuse>(p, slot, si, bsdf, mapped, wo_local, u);
  continue_path<kPlainDiffuse>(p, slot, si, bsdf, mapped, wo_local, u);
}

template <class Mode>
template <bool kPlainDiffuse>
void WavefrontIntegrator<Mode>::add_surface_emission(Paths& p, std::uint32_t slot, const SurfaceInteraction& si) const {
  const Material& material = scene_.materials[si.material];
  const Spectrum<Mode>& beta = p.throughput[slot];
  Spectrum<Mode>& L = p.radiance[slot];
  const Wavelengths<Mode>& wl = p.wavelengths[slot];
  float w = 1.0f;
  if (!p.prev_specular[slot] && use_nee_) {
    if (weight_bsdf_hits_) {
      const float light_pdf = lights_.pdf_triangle(p.hit[slot].mesh, p.hit[slot].triangle, p.prev_position[slot],
                                                   si.position, p.prev_normal[slot]);
      w = power_heuristic(p.prev_pdf[slot], light_pdf);
    } else {
      w = 0.0f;  // NEE only: emitters found by BSDF sampling are left to light sampling
    }
  }
  const bool textured = !kPlainDiffuse && shading_.has_texture(material.emission.texture, si.mesh);
  if (textured) {
    const float lod = shading_.emission_level_of_detail(material, si, p.cone_width[slot], p.prev_specular[slot]);
    L += beta * shading_.textured_emitted_radiance(si.material, si.uv, lod, wl) * w;
  } else {
    L += beta * untextured_emission(p, slot, si.material) * w;
  }
}

template <class Mode>
template <bool kPlainDiffuse, class SurfaceBsdf>
void WavefrontIntegrator<Mode>::queue_shadow_ray(Paths& p, std::uint32_t slot, const SurfaceInteraction& si,
                                                 const SurfaceBsdf& bsdf, const MappedFrame& mapped,
                                                 const Vec3f& wo_local, const BounceSamples& u) const {
  const Spectrum<Mode>& beta = p.throughput[slot];
  const Wavelengths<Mode>& wl = p.wavelengths[slot];
  // Rare (an opt-in mode on mapped materials): told so, GCC keeps the BSDF's own calls
  // inlined on the common path.
  const bool on_microsurface = !kPlainDiffuse && __builtin_expect(mapped.microsurface.has_value(), 0);
  if (const auto ls = lights_.sample(si.position, u.light_select, u.light, si.shading.n)) {
    const Vec3f wi_local = si.shading.to_local(ls->wi);
    // The geometric and the shading side must agree, or light leaks through edges.
    if ((dot(ls->wi, si.geometric_normal) > 0.0f) == (wi_local.z > 0.0f) && ls->pdf > 0.0f) {
      // (the microsurface_* functions are found by argument-dependent lookup, in prism::bsdf)
      const bool weighted = !ls->is_delta && weight_bsdf_hits_;
      float bsdf_pdf = 0.0f;
      const Spectrum<Mode> f = [&] {
        if constexpr (!kPlainDiffuse)
          if (on_microsurface) return microsurface_eval(bsdf, *mapped.microsurface, wo_local, wi_local);
        return bsdf.eval_with_pdf(wo_local, wi_local, weighted, bsdf_pdf);
      }();
      if (!f.is_black()) {
        float w = 1.0f;
        if (weighted) {
          if constexpr (!kPlainDiffuse)
            if (on_microsurface) bsdf_pdf = microsurface_pdf(bsdf, *mapped.microsurface, wo_local, wi_local);
          w = power_heuristic(ls->pdf, bsdf_pdf);
        }
        const Vec3f origin = offset_ray_origin(si.position, si.geometric_normal, ls->wi);
        float t_max;
        Vec3f dir = ls->wi;
        if (std::isinf(ls->distance)) {
          t_max = std::numeric_limits<float>::infinity();
        } else {
          const Vec3f target = ls->is_delta ? ls->position : offset_ray_origin(ls->position, ls->normal, -ls->wi);
          const Vec3f segment = target - origin;
          const float len = length(segment);
          dir = segment / len;
          t_max = len * (1.0f - 1e-4f);
        }
        p.shadow_ray[slot] = Ray{origin, dir, 0.0f, t_max};
        const Spectrum<Mode> Le =
            ls->has_rgb ? colors_.environment_radiance(ls->rgb, wl)
                        : (ls->has_uv ? shading_.textured_emitted_radiance(ls->emitter, ls->uv, 0.0f, wl)
                                      : untextured_emission(p, slot, ls->emitter)) *
                              ls->scale;
        p.shadow_contribution[slot] = beta * f * Le * (std::abs(wi_local.z) * w / ls->pdf);
        // A light inside the same absorbing medium: the shadow ray's whole length runs
        // through it (leaving it needs a crossing, which blocks the shadow ray).
        if (p.inside_absorbing[slot])
          p.shadow_contribution[slot] *=
              beer_lambert_transmittance(p.interior_sigma[slot], std::isinf(ls->distance) ? ls->distance : t_max);
        p.shadow_pending[slot] = 1;
      }
    }
  }
}

template <class Mode>
template <bool kPlainDiffuse, class SurfaceBsdf>
void WavefrontIntegrator<Mode>::continue_path(Paths& p, std::uint32_t slot, const SurfaceInteraction& si,
                                              const SurfaceBsdf& bsdf, const MappedFrame& mapped,
                                              const Vec3f& wo_local, const BounceSamples& u) const {
  Spectrum<Mode>& beta = p.throughput[slot];
  const Wavelengths<Mode>& wl = p.wavelengths[slot];
  const Material& material = scene_.materials[si.material];
  const bool on_microsurface = !kPlainDiffuse && __builtin_expect(mapped.microsurface.has_value(), 0);
  const auto bs = [&] {
    if constexpr (!kPlainDiffuse)
      if (on_microsurface) return microsurface_sample(bsdf, *mapped.microsurface, wo_local, u.lobe, u.direction, facet_numbers(p, slot));
    return bsdf.sample(wo_local, u.lobe, u.direction);
  }();
  if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) {
    p.finished[slot] = 1;
    return;
  }
  const Vec3f wi = si.shading.to_world(bs->wi);
  // A direction on the other geometric side than its shading side says it is on would
  // pass through the mesh (shading-normal artefact): end the path there.
  if ((dot(wi, si.geometric_normal) > 0.0f) != (bs->wi.z > 0.0f)) {
    p.finished[slot] = 1;
    return;
  }
  beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
  p.eta_scale[slot] *= bs->eta * bs->eta;
  // Refraction through a solid dielectric's surface: in through its front face (the side
  // its geometric normal faces), out through its back face. A medium left is always the
  // one the path is in (media do not nest here); thin-walled surfaces have no inside.
  if (bs->is_transmission && material.type == MaterialType::dielectric && !material.thin_walled) {
    p.inside_absorbing[slot] = si.front_face && material.absorbs_inside();
    if (p.inside_absorbing[slot])
      p.interior_sigma[slot] =
          absorption_coefficient(colors_.reflectance(material.attenuation_color, wl), material.attenuation_distance);
  }
  p.prev_pdf[slot] = bs->pdf;
  p.prev_specular[slot] = bs->is_specular;
  // After a glossy or diffuse bounce the cone widens to roughly the lobe's extent; a
  // fixed spread is the simple variant of the ray-cone method (Akenine-Möller et al.).
  if (!bs->is_specular) p.cone_spread[slot] = std::max(p.cone_spread[slot], 0.05f);
  p.prev_position[slot] = si.position;
  p.prev_normal[slot] = si.shading.n;
  p.depth[slot] += 1;

  // Russian roulette (Arvo & Kirk 1990): survive with probability max throughput,
  // dividing by it keeps the estimator unbiased. Radiance crossing into a denser medium
  // is scaled by 1/η²; the decision uses the throughput without that factor (pbrt-v4's
  // etaScale) so refraction alone does not kill paths.
  if (p.depth[slot] >= settings_.russian_roulette_depth) {
    float max_beta = 0.0f;
    for (int i = 0; i < Mode::kChannels; ++i) max_beta = std::max(max_beta, beta[i]);
    const float survive = std::min(1.0f, max_beta * p.eta_scale[slot]);
    if (u.roulette >= survive) {
      p.finished[slot] = 1;
      return;
    }
    beta *= 1.0f / survive;
  }
  p.ray[slot] = Ray{offset_ray_origin(si.position, si.geometric_normal, wi), wi};
}

template <class Mode>
PassStatistics WavefrontIntegrator<Mode>::render_samples(Film& film, std::uint32_t first_sample, std::uint32_t count,
                                                         int bounces_per_pass,
                                                         const std::function<void()>* after_bounces,
                                                         const std::uint8_t* active) {
  if (regenerate_) return run_wave(film, first_sample, count, bounces_per_pass, after_bounces, active);
  PassStatistics total;
  for (std::uint32_t s = 0; s < count; ++s) {
    const PassStatistics wave = run_wave(film, first_sample + s, 1, bounces_per_pass, after_bounces, active);
    total.add_counts(wave);
    total.steps += wave.steps;
    total.live_paths_per_step.insert(total.live_paths_per_step.end(), wave.live_paths_per_step.begin(),
                                     wave.live_paths_per_step.end());
  }
  return total;
}

namespace {

// Runs body(begin, end) over [0, count): split across the thread pool, or in one call on
// this thread (a tile's queue, whose thread is already one of the pool's).
void for_range(bool parallel, std::size_t count, std::size_t grain,
               const std::function<void(std::size_t, std::size_t)>& body) {
  if (parallel)
    parallel_for(count, grain, body);
  else if (count > 0)
    body(0, count);
}

}  // namespace

template <class Mode>
PassStatistics WavefrontIntegrator<Mode>::run_wave(Film& film, std::uint32_t first_sample, std::uint32_t count,
                                                   int bounces_per_pass, const std::function<void()>* after_bounces,
                                                   const std::uint8_t* active) {
  const auto pixels = static_cast<std::uint32_t>(film.pixel_count());
  const bool aovs = film.aovs().first_hit();
  // Whether slot s of `p` renders this pass: always, unless adaptive sampling has stopped
  // its pixel (`active`).
  const auto renders = [active](const Paths& p, std::uint32_t s) {
    return active == nullptr || active[p.first_pixel + s] != 0;
  };
  // Slots [begin, end) of `p` are to render samples [first_sample, first_sample + count)
  // of pixels p.first_pixel + begin …: set_up, then start with the first one. Every slot
  // of a block is set up before any starts (a camera packet waits for the lanes that will
  // take it; a stopped pixel's slot ends where it starts, so none waits for it).
  const auto set_up = [&](Paths& p, std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t s = begin; s < end; ++s) {
      p.sample_end[s] = renders(p, s) ? first_sample + count : first_sample;
      p.camera_next_sample[s] = first_sample;
      if (sobol_lanes_) p.sobol_pixel_key[s] = padded_sobol_pixel_key(seed_, p.first_pixel + s);
    }
  };
  const auto start = [&](Paths& p, std::uint32_t begin, std::uint32_t end) {
    constexpr std::uint32_t kRun = 256;
    std::array<std::uint32_t, kRun> slots, samples;
    samples.fill(first_sample);
    for (std::uint32_t first = begin; first < end; first += kRun) {
      const std::uint32_t n = std::min(kRun, end - first);
      std::uint32_t started = 0;
      for (std::uint32_t k = 0; k < n; ++k) {
        slots[started] = first + k;
        started += active == nullptr || renders(p, first + k);
      }
      generate(p, slots.data(), samples.data(), started);
    }
  };
  // The queue of slots [0, n): those that render.
  const auto initial_queue = [&](const Paths& p, std::uint32_t n) {
    std::vector<std::uint32_t> live(n);
    std::uint32_t queued = 0;
    for (std::uint32_t s = 0; s < n; ++s) {
      live[queued] = s;
      queued += active == nullptr || renders(p, s);
    }
    live.resize(queued);
    return live;
  };

  // Lockstep: one queue for the whole image, each stage split across the threads, so that
  // after every bounces_per_pass steps every pixel's path has advanced equally.
  if (bounces_per_pass > 0 && after_bounces && *after_bounces) {
    if (!whole_image_paths_ || whole_image_paths_->capacity() != pixels)
      whole_image_paths_ = std::make_unique<Paths>(pixels, kWholeImageCameraPacketsPerBlock, /*shared=*/true);
    Paths& p = *whole_image_paths_;
    p.first_hit_aovs.resize(aovs ? pixels : 0u);
    p.start_wave();
    std::vector<std::uint32_t> live = initial_queue(p, pixels);
    parallel_for(pixels, 4096, [&](std::size_t b, std::size_t e) {
      set_up(p, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e));
    });
    parallel_for(pixels, 4096, [&](std::size_t b, std::size_t e) {
      start(p, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e));
    });
    return run_queue(film, p, live, /*parallel=*/true, bounces_per_pass, after_bounces);
  }

  // Tiles: each thread takes a run of kWavefrontTilePixels pixels and runs their whole wave alone,
  // in a path state of its own (≈ 290 B per slot and 512 B of camera packets, 0.8 MB per
  // tile) that stays in the core's caches for every stage, where a whole-image queue streams its state from memory once
  // per stage; the threads meet once per pass instead of three times per step, and the
  // path state is a few tiles' worth instead of one slot per pixel. A slot is still one
  // pixel and renders its samples in order, so the image is bitwise that of the lockstep
  // queue (wavefront_integrator.h, "Determinism").
  const std::size_t tiles = (pixels + kWavefrontTilePixels - 1) / kWavefrontTilePixels;
  std::vector<PassStatistics> per_tile(tiles);
  parallel_for(tiles, 1, [&](std::size_t tb, std::size_t te) {
    for (std::size_t t = tb; t < te; ++t) {
      const auto begin = static_cast<std::uint32_t>(t * kWavefrontTilePixels);
      const auto end = static_cast<std::uint32_t>(std::min<std::size_t>(pixels, (t + 1) * kWavefrontTilePixels));
      if (active && std::none_of(active + begin, active + end, [](std::uint8_t a) { return a != 0; })) continue;
      std::unique_ptr<Paths> p = acquire_tile_paths();
      p->first_pixel = begin;
      p->first_hit_aovs.resize(aovs ? kWavefrontTilePixels : 0u);
      p->start_wave();
      std::vector<std::uint32_t> live = initial_queue(*p, end - begin);
      set_up(*p, 0, end - begin);
      start(*p, 0, end - begin);
      per_tile[t] = run_queue(film, *p, live, /*parallel=*/false, 0, nullptr);
      release_tile_paths(std::move(p));
    }
  });
  // Per-step figures add up across tiles step by step (each tile counts its own steps).
  PassStatistics stats;
  for (const PassStatistics& t : per_tile) {
    stats.add_counts(t);
    stats.steps = std::max(stats.steps, t.steps);
    if (stats.live_paths_per_step.size() < t.live_paths_per_step.size())
      stats.live_paths_per_step.resize(t.live_paths_per_step.size(), 0u);
    for (std::size_t k = 0; k < t.live_paths_per_step.size(); ++k)
      stats.live_paths_per_step[k] += t.live_paths_per_step[k];
  }
  return stats;
}

// One tile's path state per thread at most: a tile takes one from the pool (or makes one)
// and gives it back when its wave ends, so the pool grows to the number of threads that
// ran tiles at once and is reused by every later pass.
template <class Mode>
std::unique_ptr<typename WavefrontIntegrator<Mode>::Paths> WavefrontIntegrator<Mode>::acquire_tile_paths() {
  {
    const std::lock_guard<std::mutex> lock(tile_paths_mutex_);
    if (!idle_tile_paths_.empty()) {
      std::unique_ptr<Paths> p = std::move(idle_tile_paths_.back());
      idle_tile_paths_.pop_back();
      return p;
    }
  }
  return std::make_unique<Paths>(kWavefrontTilePixels, kTileCameraPacketsPerBlock, /*shared=*/false);
}

template <class Mode>
void WavefrontIntegrator<Mode>::release_tile_paths(std::unique_ptr<Paths> p) {
  const std::lock_guard<std::mutex> lock(tile_paths_mutex_);
  idle_tile_paths_.push_back(std::move(p));
}

template <class Mode>
PassStatistics WavefrontIntegrator<Mode>::run_queue(Film& film, Paths& p, std::vector<std::uint32_t>& live,
                                                    bool parallel, int bounces_per_pass,
                                                    const std::function<void()>* after_bounces) {
  PassStatistics stats;
  QueueCounts counts;
  std::vector<std::uint32_t> survivor_counts, continuing_counts;  // per compaction chunk, reused every step
  // Stage 1's queue: the live paths past their camera ray (a path's first hit comes with
  // its camera ray, generate()), in queue order; none at the first step.
  std::vector<std::uint32_t> continuing;
  continuing.reserve(live.size());
  while (!live.empty()) {
    stats.live_paths_per_step.push_back(static_cast<std::uint32_t>(live.size()));
    stats.rays += live.size();
    ++stats.steps;
    // Stage 1, intersect: closest hits of the continuing paths' rays, as Embree ray streams.
    for_range(parallel, continuing.size(), kQueueGrain, [&](std::size_t b, std::size_t e) {
      accel_.intersect_slots(p.ray.data(), continuing.data() + b, e - b, p.hit.data(), p.hit_found.data());
    });
    // Stage 2, shade: emits continuation and shadow rays.
    for_range(parallel, live.size(), kQueueGrain,
              [&](std::size_t b, std::size_t e) { shade_stage(p, live, b, e, counts); });
    // Stages 3 and 4, shadow and accumulate (and regenerate), in one walk over the queue
    // per chunk; stage 5, compact: the survivors, in queue order, in place. Each chunk
    // packs its survivors at its own start (a write never passes the read), then the
    // packed runs move down to their prefix-sum offsets; likewise the survivors that did
    // not restart, stage 1's next queue.
    const std::size_t chunks = (live.size() + kQueueGrain - 1) / kQueueGrain;
    survivor_counts.assign(chunks, 0);
    continuing_counts.assign(chunks, 0);
    continuing.resize(live.size());
    for_range(parallel, chunks, 1, [&](std::size_t cb, std::size_t ce) {
      for (std::size_t c = cb; c < ce; ++c)
        shadow_and_accumulate_stage(film, p, live, continuing, c, survivor_counts[c], continuing_counts[c], counts);
    });
    compact_queue(live, survivor_counts);
    compact_queue(continuing, continuing_counts);
    if (bounces_per_pass > 0 && after_bounces && *after_bounces && !live.empty() &&
        stats.steps % bounces_per_pass == 0)
      (*after_bounces)();
  }
  stats.shadow_rays = counts.shadow_rays.load();
  stats.invalid_samples = counts.invalid.load();
  stats.completed_samples = counts.completed.load();
  stats.lane_shaded_hits = counts.lane_shaded.load();
  stats.camera_packet_rays = p.camera_packet_rays.load();
  return stats;
}

template <class Mode>
void WavefrontIntegrator<Mode>::shade_stage(Paths& p, const std::vector<std::uint32_t>& live, std::size_t b,
                                            std::size_t e, QueueCounts& counts) const {
  // Before shading slots[at … at + step): the indices of those twice as far on (at
  // least 8), the vertices of those as far on (at least 4).
  const auto prefetch_ahead = [&](const std::uint32_t* slots, std::size_t at, std::size_t count, std::size_t step) {
    const std::size_t indices_at = at + std::max<std::size_t>(8, 2 * step);
    const std::size_t vertices_at = at + std::max<std::size_t>(4, step);
    for (std::size_t k = indices_at; k < std::min(count, indices_at + step); ++k)
      if (p.hit_found[slots[k]]) prefetch_hit_indices(scene_, p.hit[slots[k]]);
    for (std::size_t k = vertices_at; k < std::min(count, vertices_at + step); ++k)
      if (p.hit_found[slots[k]]) prefetch_hit_vertices(scene_, p.hit[slots[k]]);
  };
  const auto width = static_cast<std::size_t>(lane_width_);
  // The chunk's slots split without branches (whether a ray hit, and what, is a coin
  // flip to a branch predictor): the hits that shades_in_lanes, shaded lane_width_ at a
  // time, the last few alone; then every other slot alone. Each slot's bits are the
  // same in any order. The same walk collects the hits' bounce-block requests.
  std::array<std::uint32_t, kQueueGrain> in_lanes, alone;
  std::array<BounceBlockRequest, 64> requests;
  for (std::size_t run = b; run < e; run += kQueueGrain) {  // a tile's queue is one range
    const std::size_t run_end = std::min(e, run + kQueueGrain);
    std::size_t in_lanes_count = 0, alone_count = 0, requested = 0;
    for (std::size_t i = run; i < run_end; ++i) {
      const std::uint32_t s = live[i];
      const bool together = shades_in_lanes(p, s);
      in_lanes[in_lanes_count] = s;
      alone[alone_count] = s;
      in_lanes_count += together;
      alone_count += !together;
      if (!sobol_lanes_) continue;  // the same for every slot
      requests[requested] = {p.sobol_pixel_key[s], p.sample_index[s], p.depth[s], &p.bounce_block[s]};
      requested += p.hit_found[s] != 0;  // a miss's request is overwritten by the next slot's
      if (requested == requests.size()) {
        padded_sobol_bounce_blocks_lanes(sampler_lanes_, {requests.data(), requested});
        requested = 0;
      }
    }
    if (sobol_lanes_) padded_sobol_bounce_blocks_lanes(sampler_lanes_, {requests.data(), requested});
    std::size_t lane_shaded_count = 0;
    for (; width > 0 && lane_shaded_count + width <= in_lanes_count; lane_shaded_count += width) {
      if (prefetch_geometry_) prefetch_ahead(in_lanes.data(), lane_shaded_count, in_lanes_count, width);
#if PRISM_FLOAT_LANES_AVX2
      if (lane_width_ == lanes::avx2::kWidth)
        shade_plain_lanes_avx2(p, in_lanes.data() + lane_shaded_count);
      else
#endif
        shade_plain_lanes(p, in_lanes.data() + lane_shaded_count);
    }
    for (std::size_t k = lane_shaded_count; k < in_lanes_count; ++k) shade(p, in_lanes[k]);
    for (std::size_t k = 0; k < alone_count; ++k) {
      if (prefetch_geometry_) prefetch_ahead(alone.data(), k, alone_count, 1);
      shade(p, alone[k]);
    }
    counts.lane_shaded += lane_shaded_count;
  }
}

template <class Mode>
void WavefrontIntegrator<Mode>::shadow_and_accumulate_stage(Film& film, Paths& p, std::vector<std::uint32_t>& live,
                                                            std::vector<std::uint32_t>& continuing, std::size_t c,
                                                            std::uint32_t& survivors,
                                                            std::uint32_t& continuing_count,
                                                            QueueCounts& counts) const {
  // The chunk's finished slots, and which of them restart: the film and the new samples
  // are done after the walk, each in a loop of its own, so that the CIE and wavelength
  // tables and the sampler stay in the L1 cache for the whole run of slots instead of
  // taking turns with the path state. Each slot's numbers are its own, so the order
  // changes nothing.
  std::array<std::uint32_t, kQueueGrain> finished, restarted, next_sample;
  std::uint64_t local_invalid = 0, traced = 0;
  std::size_t finished_count = 0, restarted_count = 0;
  const std::size_t end = std::min(live.size(), (c + 1) * kQueueGrain);
  accel_.occluded_slots(p.shadow_ray.data(), live.data() + c * kQueueGrain, end - c * kQueueGrain,
                        p.shadow_pending.data(), p.shadow_blocked.data());
  std::size_t kept = c * kQueueGrain, continues = c * kQueueGrain;
  // Without branches: whether a slot's shadow ray was traced and got through, and
  // whether its path finished, are coin flips a predictor misses on (core/branch_free.h);
  // each slot is written to every list and counted into those it belongs to.
  for (std::size_t i = c * kQueueGrain; i < end; ++i) {
    const std::uint32_t s = live[i];
    const bool pending = p.shadow_pending[s] != 0;
    traced += pending;
    p.radiance[s] = select_bits(pending & (p.shadow_blocked[s] == 0), p.radiance[s] + p.shadow_contribution[s],
                                p.radiance[s]);
    const bool finished_now = p.finished[s] != 0;
    const bool restarts = finished_now & regenerate_ & (p.sample_index[s] + 1 < p.sample_end[s]);
    finished[finished_count] = s;
    finished_count += finished_now;
    restarted[restarted_count] = s;
    restarted_count += restarts;
    live[kept] = s;
    kept += !finished_now | restarts;
    continuing[continues] = s;
    continues += !finished_now;
  }
  for (std::size_t k = 0; k < finished_count; ++k) {
    const std::uint32_t s = finished[k];
    const Vec3d value = colors_.to_film(p.radiance[s], p.wavelengths[s]);
    if (is_finite(value)) {
      film.add_sample(p.first_pixel + s, value);
      if (!p.first_hit_aovs.empty()) film.add_aov_sample(p.first_pixel + s, p.first_hit_aovs[s]);
    } else {
      ++local_invalid;  // never written to the film; reported at the end
    }
  }
  for (std::size_t k = 0; k < restarted_count; ++k) next_sample[k] = p.sample_index[restarted[k]] + 1;
  generate(p, restarted.data(), next_sample.data(), restarted_count);
  survivors = static_cast<std::uint32_t>(kept - c * kQueueGrain);
  continuing_count = static_cast<std::uint32_t>(continues - c * kQueueGrain);
  counts.invalid += local_invalid;
  counts.completed += finished_count;
  counts.shadow_rays += traced;
}

template <class Mode>
void WavefrontIntegrator<Mode>::compact_queue(std::vector<std::uint32_t>& queue,
                                              const std::vector<std::uint32_t>& counts) {
  std::size_t packed = 0;
  for (std::size_t c = 0; c < counts.size(); ++c) {
    const auto first = queue.begin() + static_cast<std::ptrdiff_t>(c * kQueueGrain);
    std::copy(first, first + counts[c], queue.begin() + static_cast<std::ptrdiff_t>(packed));
    packed += counts[c];
  }
  queue.resize(packed);
}

template class WavefrontIntegrator<SpectralMode<3>>;
template class WavefrontIntegrator<SpectralMode<4>>;
template class WavefrontIntegrator<SpectralMode<8>>;
template class WavefrontIntegrator<RgbMode>;

}  // namespace prism
