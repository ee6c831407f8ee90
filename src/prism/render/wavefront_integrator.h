#pragma once
// Wavefront path tracing (Laine, Karras, Aila 2013, "Megakernels Considered Harmful"):
// path state in structs of arrays, one stage at a time over the queue of live paths —
// intersect, shade (emission, next-event estimation with MIS, BSDF sampling, Russian
// roulette), shadow rays, then completion. A finished path is regenerated at once with its
// pixel's next sample, so the queue stays full and step times stay steady; queues are
// compacted every step, so only live paths are traced. Hits on plain diffuse materials are
// shaded several at a time, in SIMD lanes (shade_plain_lanes), to the same bits; the
// stages' walks over the queue decide which list a slot joins (hit or miss, lanes or not,
// shadow ray or not, finished or not) with masks and counts, not branches, since those
// are coin flips to a branch predictor (docs/performance-design.md "Sampler blocks and branch-free
// walks"). The image is cut into tiles of kWavefrontTilePixels pixels, one queue each, and
// each thread runs whole tiles: a tile's path state stays in cache across the stages
// (1.07× at 256², 1.13× at 512², one thread; docs/performance-design.md "Tiles and path state"). Only a
// pass that reports every few bounces keeps one queue for the whole image, stepped in
// lockstep with each stage split across the threads.
//
// Camera rays are traced in fixed packets (render/camera_packet_cache.h): those of eight
// neighbouring pixels at one sample index, always together, about 0.4 × the time of the
// same rays one by one; a path's first hit comes with its camera ray.
//
// Determinism: every pixel owns one path slot and renders its samples in order; a
// sample's random numbers depend only on (seed, pixel, sample index, dimension)
// (sampling/pixel_sampler.h, which also fixes the dimension layout), a camera packet only
// on its pixels and sample index, and the film adds a pixel's samples in sample order. The
// image is therefore bitwise independent of thread count and scheduling, and of how
// samples are grouped into passes.
#include <array>
#include <atomic>
#include <memory>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/bsdf/microfacet_normal_mapping.h"
#include "prism/bsdf/normal_mapping_model.h"
#include "prism/core/lane_slots.h"
#include "prism/core/mat3.h"
#include "prism/render/aov.h"
#include "prism/render/camera_packet_cache.h"
#include "prism/render/color_context.h"
#include "prism/render/film.h"
#include "prism/render/light_estimator.h"
#include "prism/render/material_bsdf.h"
#include "prism/render/simd_level.h"
#include "prism/render/surface_shading.h"
#include "prism/sampling/pixel_sampler.h"
#include "prism/scene/camera_rays.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/scene.h"
#include "prism/scene/texture_sampling.h"

namespace prism {

struct SurfaceInteraction;

struct PathSettings {
  // Scattering events; 1 = direct lighting only, 0 = emission only. 64: a cap that cuts off
  // no measurable energy. Russian roulette (after russian_roulette_depth) already ends paths
  // in proportion to their throughput, so the cap only truncates the rare long paths: a cap
  // of 8 made the Cornell box 0.34 % darker than 64 (a bias) and saved about 3 % of its CPU
  // time (docs/display-pipeline.md "Bounce limit").
  int max_depth = 64;
  int russian_roulette_depth = 3;  // roulette starts after this many bounces
  LightEstimator estimator = LightEstimator::mis;  // render/light_estimator.h
  // Where each path's random numbers come from. sobol is the default by measurement
  // (BENCHMARKS.md "sampler": about half the RMSE of independent sampling at 256 spp on the
  // Cornell box, also at equal time).
  SamplerKind sampler = SamplerKind::sobol;
  // How next-event estimation picks an emitter and a point on it (scene/light_sampler.h,
  // scene/triangle_light_sampling.h); the defaults by measurement (BENCHMARKS.md "Peer").
  LightSamplerOptions light;
  NormalMapping normal_mapping = NormalMapping::classic;  // bsdf/normal_mapping_model.h
  // The SIMD the fast paths may use (render/simd_level.h): the same image at every level.
  SimdLevel simd = SimdLevel::automatic;
};

// Pixels per tile: a tile's queue is run by one thread from its first step to its last, in
// a path state of its own (unless a pass reports after every few bounces, which keeps one
// whole-image queue). Any size gives the same image. 1024 to 16384 measured alike until
// camera packets; since, 1024, whose path state and camera packets (≈ 300 + 512 KiB) fit a
// 1 MiB L2 cache, measured best (docs/performance-design.md "Tiles and path state").
inline constexpr std::size_t kWavefrontTilePixels = 1024;
// Camera packets kept per block of pixels (camera_packet_cache.h): in a tile's path state,
// and in the whole-image queue's, which has one slot per pixel of the image (there each
// packet kept costs 64 B a pixel). More only trace fewer packets twice; the image is the
// same. Passes of P samples let a block's pixels drift apart by about P / 2 samples: in a
// tile, 8 kept trace 1.00 / 1.07 / 1.40 × the camera rays at 8 / 16 / 32 samples a pass
// on the Cornell box, and 16 kept (1.00 / 1.00 / 1.07 ×) measured slower, their
// 1 MiB no longer in L2; the whole-image queue's 4 (1.09 / 1.52 / 2.28 ×) keep a camera
// ray below the 46 ns it takes alone at any pass length (18 ns in a packet; BENCHMARKS.md
// "Camera rays in fixed packets").
inline constexpr std::size_t kTileCameraPacketsPerBlock = 8;
inline constexpr std::size_t kWholeImageCameraPacketsPerBlock = 4;
// Path state bytes per slot the camera packets add (the memory estimate's figure).
constexpr std::size_t camera_packet_bytes_per_slot(std::size_t packets_per_block) {
  return packets_per_block * (sizeof(CameraPacketCache::Packet) + sizeof(std::uint32_t) + 1) /
             CameraPacketCache::kLanes +
         sizeof(std::uint32_t);
}

struct PassStatistics {
  std::uint64_t rays = 0;             // closest-hit rays (camera and continuation)
  std::uint64_t shadow_rays = 0;
  std::uint64_t invalid_samples = 0;  // NaN/Inf radiance discarded
  std::uint64_t completed_samples = 0;
  std::uint64_t lane_shaded_hits = 0;  // hits shaded several at a time (shade_plain_lanes)
  // Rays traced in camera packets: a packet's every pixel's, needed or not, and again where
  // the packet had to be traced again (camera_packet_cache.h). At least one per sample.
  std::uint64_t camera_packet_rays = 0;
  int steps = 0;
  std::vector<std::uint32_t> live_paths_per_step;
  // Adds another queue's ray and sample counts (the per-step figures are the caller's).
  void add_counts(const PassStatistics& other) {
    rays += other.rays;
    shadow_rays += other.shadow_rays;
    invalid_samples += other.invalid_samples;
    completed_samples += other.completed_samples;
    lane_shaded_hits += other.lane_shaded_hits;
    camera_packet_rays += other.camera_packet_rays;
  }
};

template <class Mode>
class WavefrontIntegrator {
 public:
  ~WavefrontIntegrator();
  // `mip_pyramids`: one per Scene::textures entry (PreparedScene::mip_pyramids(), built once
  // per prepared scene, not per render).
  WavefrontIntegrator(const Scene& scene, const EmbreeAccel& accel, const std::vector<MipPyramid>& mip_pyramids,
                      const LightSampler& lights,
                      const PinholeCamera& camera, const ColorContext<Mode>& colors, const PathSettings& settings,
                      int width, int height, std::uint64_t seed, bool regenerate = true);

  // Renders samples [first_sample, first_sample + count) of every pixel into `film`.
  // With regeneration off, each of the `count` samples is a separate wave (for measuring
  // what regeneration buys).
  // Bounces per pass (the seed renderer's "#Bounce/Frame"): with bounces_per_pass > 0 and
  // `after_bounces` set, after every bounces_per_pass wavefront steps (each advances every
  // live path by one bounce) while paths are still in flight, `after_bounces` is called
  // with the film as it is: every pixel's completed samples, so a viewer can show progress
  // on deep paths. It changes neither the film's final contents nor their order.
  // `active` (adaptive sampling, render/adaptive_sampling.h): one byte per pixel, nonzero
  // for the pixels that render this pass; the others' slots are never generated nor
  // queued (a camera packet still traces their lanes: a packet is always the same rays).
  // Null: every pixel, the path taken before adaptive sampling existed.
  PassStatistics render_samples(Film& film, std::uint32_t first_sample, std::uint32_t count,
                                int bounces_per_pass = 0, const std::function<void()>* after_bounces = nullptr,
                                const std::uint8_t* active = nullptr);

 private:
  struct Paths;  // structure of arrays, one slot per pixel of a tile (or of the image)
  // Starts sample sample_indices[k] of slot slots[k]'s pixel, for k < count: its camera ray
  // and wavelengths, and a fresh path state.
  void generate(Paths& paths, const std::uint32_t* slots, const std::uint32_t* sample_indices,
                std::size_t count) const;
  // Slot's lane of its block's camera packet of `sample`, traced first where the block
  // does not hold it: the ray and its hit to the slot, the wavelength number to
  // `wavelength_number`.
  // `numbers`: room for a packet's camera numbers, made once per run of slots.
  using PacketNumbers = LaneSlots<CameraSamples, EmbreeAccel::kPacketRays>;
  void take_camera_lane(Paths& paths, std::uint32_t slot, std::uint32_t sample, double& wavelength_number,
                        PacketNumbers& numbers) const;
  // Traces block's camera packet of `sample` for `slot`, which takes its lane at once, into
  // the block's cache; returns its index there.
  std::size_t trace_camera_packet(Paths& paths, std::size_t block, std::uint32_t sample, std::uint32_t slot,
                                  PacketNumbers& numbers) const;
  void shade(Paths& paths, std::uint32_t slot) const;
  // shade() past the hit's geometry. kPlainDiffuse: the material is_plain_diffuse
  // (material_bsdf.h), and the steps it cannot take (maps, anisotropy, textures, layers,
  // other lobes) are compiled out; the steps left are the same, in the same order, so a
  // plain hit shades to the same bits either way.
  template <bool kPlainDiffuse>
  void shade_surface(Paths& paths, std::uint32_t slot, SurfaceInteraction& si) const;
  // shade_surface's stages, inlined into it (each runs once per hit; apart only to be read
  // one at a time). `mapped`: the frame after the material's maps (SurfaceShading).
  using MappedFrame = typename SurfaceShading<Mode>::MappedFrame;
  // The hit emitter's radiance, MIS-weighted against light sampling, into the path.
  template <bool kPlainDiffuse>
  [[gnu::always_inline]] inline void add_surface_emission(Paths& paths, std::uint32_t slot,
                                                          const SurfaceInteraction& si) const;
  // Next-event estimation: a light sample, its contribution and its shadow ray, which
  // stage 3 traces (Paths::shadow_pending).
  template <bool kPlainDiffuse, class SurfaceBsdf>
  [[gnu::always_inline]] inline void queue_shadow_ray(Paths& paths, std::uint32_t slot, const SurfaceInteraction& si,
                                                      const SurfaceBsdf& bsdf, const MappedFrame& mapped,
                                                      const Vec3f& wo_local, const BounceSamples& u) const;
  // The BSDF sample that continues the path, the medium it enters, Russian roulette.
  template <bool kPlainDiffuse, class SurfaceBsdf>
  [[gnu::always_inline]] inline void continue_path(Paths& paths, std::uint32_t slot, const SurfaceInteraction& si,
                                                   const SurfaceBsdf& bsdf, const MappedFrame& mapped,
                                                   const Vec3f& wo_local, const BounceSamples& u) const;
  // Whether shade() of the slot's hit may run in lanes (shade_plain_lanes): a hit on a mesh
  // of lane_mesh_, on the path's first segment outside a medium, with a bounce left, and
  // no AOVs to record.
  bool shades_in_lanes(const Paths& paths, std::uint32_t slot) const;
  // shade() of four such hits at once (wavefront_plain_lanes.cpp): the same steps
  // in the same order, the geometry and direction arithmetic of all the lanes in one
  // instruction each (core/float_lanes.h), the spectra and the light sampler lane by lane.
  // Each slot gets the bits shade() gives it.
  void shade_plain_lanes(Paths& paths, const std::uint32_t* slots) const;
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  // The same for eight hits, in AVX2 (lanes::avx2): only where the processor has AVX2.
  [[gnu::target("avx2")]] void shade_plain_lanes_avx2(Paths& paths, const std::uint32_t* slots) const;
#endif
  // Microfacet normal mapping's two numbers for the slot's current bounce (pixel_sampler.h).
  Vec2f facet_numbers(const Paths& paths, std::uint32_t slot) const;
  // The numbers `needs` asks for of the slot's current bounce block: from the block drawn
  // ahead of shading (Paths::bounce_block) where sobol_lanes_, else drawn now.
  BounceSamples bounce_numbers(const Paths& paths, std::uint32_t slot, unsigned needs) const;
  // The sampler's key of the slot's current sample.
  PixelSample pixel_sample(const Paths& paths, std::uint32_t slot) const;
  // An untextured emitter's spectrum at the wavelengths of slot's path, through the path's
  // one-entry cache.
  static constexpr std::uint32_t kNoCachedEmitter = ~std::uint32_t{0};
  Spectrum<Mode> untextured_emission(Paths& p, std::uint32_t slot, std::uint32_t emitter) const;
  PassStatistics run_wave(Film& film, std::uint32_t first_sample, std::uint32_t count, int bounces_per_pass,
                          const std::function<void()>* after_bounces, const std::uint8_t* active);
  // Steps the queue `live` (generated slots) until every path in it has its samples:
  // each stage split across the threads (`parallel`) or run on this thread (a tile).
  PassStatistics run_queue(Film& film, Paths& paths, std::vector<std::uint32_t>& live, bool parallel,
                           int bounces_per_pass, const std::function<void()>* after_bounces);
  // The queue's stages work on chunks of this many slots (a tile's queue is one chunk).
  static constexpr std::size_t kQueueGrain = 1024;
  struct QueueCounts {
    std::atomic<std::uint64_t> shadow_rays{0}, invalid{0}, completed{0}, lane_shaded{0};
  };
  // Stage 2, shade, of live[b, e): plain diffuse hits in lanes, the rest alone; the
  // geometry of hits a few slots ahead prefetched where it outgrows the caches
  // (surface_interaction.h), and the hits' bounce blocks drawn first where that is cheap
  // (sobol_lanes_).
  void shade_stage(Paths& paths, const std::vector<std::uint32_t>& live, std::size_t b, std::size_t e,
                   QueueCounts& counts) const;
  // Stages 3 and 4 of chunk c of the queue: its shadow rays traced (one stream), finished
  // paths added to the film and their slots restarted with the pixel's next sample
  // (regeneration). The chunk's survivors (and those of them that did not restart, stage
  // 1's next queue) are packed at its start: `survivors` and `continuing_count` say how many.
  void shadow_and_accumulate_stage(Film& film, Paths& paths, std::vector<std::uint32_t>& live,
                                   std::vector<std::uint32_t>& continuing, std::size_t c, std::uint32_t& survivors,
                                   std::uint32_t& continuing_count, QueueCounts& counts) const;
  // Stage 5, compact: moves each chunk's packed run (counts[c] slots at c · kQueueGrain)
  // down to its prefix-sum offset, in queue order.
  static void compact_queue(std::vector<std::uint32_t>& queue, const std::vector<std::uint32_t>& counts);
  std::unique_ptr<Paths> acquire_tile_paths();
  void release_tile_paths(std::unique_ptr<Paths> paths);

  std::mutex tile_paths_mutex_;
  std::vector<std::unique_ptr<Paths>> idle_tile_paths_;  // tile path states not in use
  std::unique_ptr<Paths> whole_image_paths_;             // lockstep queue's, made on first use
  SurfaceShading<Mode> shading_;  // what a hit does, shared with the reference path tracer
  std::vector<std::uint8_t> plain_diffuse_;  // per material: is_plain_diffuse
  // Per mesh: a plain diffuse material that does not emit, and no tangents (whose frames
  // the lanes do not build), so shade_plain_lanes can shade its hits. All zero where
  // the lanes are off (lane_width_ 0).
  std::vector<std::uint8_t> lane_mesh_;
  const Scene& scene_;
  const EmbreeAccel& accel_;
  const LightSampler& lights_;
  const PinholeCamera& camera_;
  const ColorContext<Mode>& colors_;
  PathSettings settings_;
  int width_, height_;
  std::uint64_t seed_;
  bool regenerate_;
  bool prefetch_geometry_ = false;  // the meshes outgrow the caches: shading prefetches hits' vertices
  // The padded Sobol' sampler runs on its lanes (whole_bounce_blocks_are_cheap), so its
  // blocks are drawn in batches from each slot's pixel key (Paths::sobol_pixel_key): every
  // hit's bounce block whole for the queue before shading (Paths::bounce_block), and the
  // camera blocks of each run of new samples; two blocks at a time with AVX-512. The draws
  // of a queue are independent of one another and overlap, where inside shade() they are a
  // link in each path's chain of dependent work (docs/performance-design.md "Sampler blocks and
  // branch-free walks").
  bool sobol_lanes_ = false;
  SobolLanes sampler_lanes_ = SobolLanes::none;  // settings_.simd's lanes for the sampler
  bool use_nee_ = false;           // light samples at non-specular vertices (not bsdf_only, and lights exist)
  bool weight_bsdf_hits_ = false;  // MIS: light samples and emitters found by BSDF sampling weighted against each other
  // Hits on lane_mesh_ meshes are shaded lane_width_ at a time: eight with AVX2
  // (shade_plain_lanes_avx2), four with SSE2 (shade_plain_lanes), or each alone (0), as
  // settings_.simd says (shading_lane_width); the image is the same.
  int lane_width_ = 0;
  static constexpr int kMaxLaneWidth = 8;
};

}  // namespace prism
