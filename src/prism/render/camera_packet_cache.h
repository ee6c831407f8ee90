#pragma once
// Camera rays in fixed packets. Embree traces a packet of neighbouring camera rays in
// about 0.4 × the time of the same rays one by one (docs/performance-design.md "Camera rays in fixed
// packets"), but where two triangles lie at exactly the same distance along a ray, which
// one a packet reports depends on its other rays (accel/embree_accel.h, RayCoherence). So
// the integrator's camera packets never change: a block is kLanes consecutive pixel
// indices, aligned, and its packet of sample s is the camera rays of those pixels at
// sample s, always traced together with the same lanes, whichever of their paths happen to
// restart together (wavefront_integrator.h, "Determinism").
//
// The pixels of a block start sample s at different steps of the wavefront (their paths
// have different lengths), so a block keeps a few packets, each until every lane that
// still needs it has taken it. This class holds them; the integrator traces them. Each
// lane keeps what its path starts from: the camera ray, its hit, and the number the
// path's wavelengths are drawn from; one cache line, read once, by one path.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/sampling/pixel_sampler.h"

namespace prism {

class CameraPacketCache {
 public:
  static constexpr std::size_t kLanes = EmbreeAccel::kPacketRays;
  static constexpr std::uint32_t kNoSample = ~std::uint32_t{0};

  struct alignas(64) Lane {
    Ray ray;
    Hit hit;
    std::uint32_t found;  // the ray hit something (hit holds it)
    double wavelength;    // CameraSamples::wavelength
  };
  static_assert(sizeof(Lane) == 64, "a lane is one cache line");
  struct Packet {
    std::array<Lane, kLanes> lanes;
  };

  // Room for the blocks of `slots` consecutive slots (the first one aligned), each with
  // `packets_per_block` packets.
  CameraPacketCache(std::size_t slots, std::size_t packets_per_block)
      : per_block_(packets_per_block), blocks_((slots + kLanes - 1) / kLanes),
        samples_(blocks_ * per_block_, kNoSample), waiting_(blocks_ * per_block_, 0),
        packets_(blocks_ * per_block_) {}

  std::size_t blocks() const { return blocks_; }

  // Forgets every packet.
  void clear() {
    std::fill(samples_.begin(), samples_.end(), kNoSample);
    std::fill(waiting_.begin(), waiting_.end(), std::uint8_t{0});
  }

  // The index of block's packet of `sample`, or -1 where it does not hold it. Without
  // branches: which of the block's packets it is, is a coin flip to a branch predictor.
  std::ptrdiff_t find(std::size_t block, std::uint32_t sample) const {
    const std::size_t first = block * per_block_;
    std::ptrdiff_t at = -1;
    for (std::size_t k = first; k < first + per_block_; ++k)
      at = samples_[k] == sample ? static_cast<std::ptrdiff_t>(k) : at;
    return at;
  }

  // Room for block's packet of `sample`, whose lanes in `waiting` will each be taken
  // once: a packet whose lanes have all been taken, else the one of the highest sample
  // (its lanes are the furthest from being needed: the block's slower pixels take them
  // after every lower sample), which is dropped and traced again when needed. The caller
  // fills the packet.
  std::size_t claim(std::size_t block, std::uint32_t sample, std::uint8_t waiting) {
    const std::size_t first = block * per_block_;
    std::size_t at = first;
    for (std::size_t k = first; k < first + per_block_; ++k) {
      if (waiting_[k] == 0) {
        at = k;
        break;
      }
      if (samples_[k] > samples_[at]) at = k;
    }
    samples_[at] = waiting != 0 ? sample : kNoSample;
    waiting_[at] = waiting;
    return at;
  }

  Packet& packet(std::size_t index) { return packets_[index]; }
  const Packet& packet(std::size_t index) const { return packets_[index]; }

  // Marks `lane` of the packet taken; the packet's room is free once every lane is.
  void take(std::size_t index, std::size_t lane) {
    waiting_[index] = static_cast<std::uint8_t>(waiting_[index] & ~(1u << lane));
    if (waiting_[index] == 0) samples_[index] = kNoSample;
  }

  std::uint8_t waiting(std::size_t index) const { return waiting_[index]; }

 private:
  std::size_t per_block_;
  std::size_t blocks_;
  std::vector<std::uint32_t> samples_;  // per packet: its sample, kNoSample where free
  std::vector<std::uint8_t> waiting_;   // per packet: the lanes not taken yet
  std::vector<Packet> packets_;
};

}  // namespace prism
