#pragma once
// The wavefront integrator's path state (WavefrontIntegrator<Mode>::Paths), shared by its
// translation units: wavefront_integrator.cpp and wavefront_plain_lanes.cpp.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "prism/render/camera_packet_cache.h"
#include "prism/render/wavefront_integrator.h"

namespace prism {

// A queue's path state, one slot per pixel of a run of pixels starting at first_pixel:
// slot s holds pixel first_pixel + s.
template <class Mode>
struct WavefrontIntegrator<Mode>::Paths {
  // `camera_packets_per_block`: CameraPacketCache's; `shared`: several threads start
  // paths in it at once (the whole-image queue), so each block's packets are locked.
  Paths(std::size_t n, std::size_t camera_packets_per_block, bool shared)
      : camera_packets(n, camera_packets_per_block), camera_next_sample(n),
        block_locks(shared ? std::make_unique<std::atomic<std::uint8_t>[]>(camera_packets.blocks()) : nullptr),
        ray(n), throughput(n), radiance(n), wavelengths(n), hit(n), hit_found(n), shadow_ray(n),
        shadow_contribution(n), shadow_pending(n), shadow_blocked(n), prev_position(n), prev_normal(n), prev_pdf(n),
        eta_scale(n), cone_width(n), cone_spread(n), prev_specular(n), depth(n), finished(n), sample_index(n),
        sample_end(n), inside_absorbing(n), interior_sigma(n), bounce_block(n), sobol_pixel_key(n), cached_emitter(n),
        cached_emission(n) {}
  std::size_t capacity() const { return ray.size(); }
  // Forgets the last wave's camera packets and their count.
  void start_wave() {
    camera_packets.clear();
    camera_packet_rays = 0;
  }
  std::uint32_t first_pixel = 0;
  // Camera rays in fixed packets (camera_packet_cache.h): the blocks' packets; per slot,
  // the first sample whose camera lane it has not taken yet; where shared, a lock per block.
  CameraPacketCache camera_packets;
  std::vector<std::uint32_t> camera_next_sample;
  std::unique_ptr<std::atomic<std::uint8_t>[]> block_locks;
  std::atomic<std::uint64_t> camera_packet_rays{0};  // lanes traced in camera packets
  std::vector<Ray> ray;
  std::vector<Spectrum<Mode>> throughput, radiance;
  std::vector<Wavelengths<Mode>> wavelengths;
  std::vector<Hit> hit;
  std::vector<std::uint8_t> hit_found;
  std::vector<Ray> shadow_ray;
  std::vector<Spectrum<Mode>> shadow_contribution;
  std::vector<std::uint8_t> shadow_pending;
  std::vector<std::uint8_t> shadow_blocked;  // the pending shadow ray hit something
  std::vector<Vec3f> prev_position;
  std::vector<Vec3f> prev_normal;          // its shading normal (triangle light pdfs depend on it)
  std::vector<float> prev_pdf;             // solid-angle pdf of the direction that led here
  std::vector<float> eta_scale;            // product of η² over refractions (for roulette)
  std::vector<float> cone_width, cone_spread;  // ray cone for texture LOD (Akenine-Möller et al. 2021)
  std::vector<std::uint8_t> prev_specular; // that direction came from a delta lobe
  std::vector<std::int32_t> depth;
  std::vector<std::uint8_t> finished;
  std::vector<std::uint32_t> sample_index, sample_end;
  // The path travels inside an absorbing dielectric (volume_absorption.h), whose σ per scene
  // unit at the path's wavelengths is interior_sigma: set on refracting in through a front
  // face, cleared on refracting out through a back face.
  std::vector<std::uint8_t> inside_absorbing;
  std::vector<Spectrum<Mode>> interior_sigma;
  // The AOVs of each slot's current sample, written by shade() at depth 0 and added to the
  // film with the sample. Empty unless the film keeps AOVs.
  std::vector<AovSample> first_hit_aovs;
  // Each hit's bounce block, drawn whole before shading where sobol_lanes_.
  std::vector<BounceSamples> bounce_block;
  // padded_sobol_pixel_key of the slot's pixel, where sobol_lanes_ (set as a wave starts).
  std::vector<std::uint64_t> sobol_pixel_key;
  // The untextured emitter whose spectrum at the path's wavelengths is cached_emission
  // (untextured_emission); kNoCachedEmitter for none yet.
  std::vector<std::uint32_t> cached_emitter;
  std::vector<Spectrum<Mode>> cached_emission;
};

// Here, not in wavefront_integrator.cpp: both shading paths call it for every hit, the
// lanes from their own translation unit.
template <class Mode>
BounceSamples WavefrontIntegrator<Mode>::bounce_numbers(const Paths& p, std::uint32_t slot, unsigned needs) const {
  return sobol_lanes_ ? only_needed(p.bounce_block[slot], needs)
                              : bounce_samples(settings_.sampler, sampler_lanes_, pixel_sample(p, slot), p.depth[slot], needs);
}

}  // namespace prism
