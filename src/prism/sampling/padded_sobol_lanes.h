#pragma once
// The padded Owen-scrambled Sobol' sampler's camera and bounce blocks (pixel_sampler.h,
// "sobol"; Burley 2020) with their requests side by side in the eight 32-bit lanes of one
// 256-bit register. A bounce block's five requests need five index shuffles and seven axis
// scrambles, each a Laine–Karras permutation and a bit reversal: twelve scalar chains of
// about 25 instructions, here two passes over one register (a bit reversal is a byte
// shuffle and two nibble-table lookups, or with GFNI one affine transform; Sobol'
// dimension 1 is computed in closed form instead of through byte tables). The request
// hashes run in four 64-bit lanes (AVX2 builds each 64-bit multiply from three 32-bit
// ones, AVX-512DQ has it), and only the requests a vertex asks for are hashed.
//
// The bits are exactly those of the scalar path (pixel_sampler_test compares them, and
// renders are bitwise the same). Chosen at run time: a build for plain x86-64 also runs on
// processors without AVX2, which take the scalar path.
#include <cstdint>
#include <span>

#include "prism/sampling/pixel_sampler.h"
#include "prism/sampling/sobol_lanes.h"

namespace prism {

// The widest lanes this build and processor run (decided once, before main).
SobolLanes padded_sobol_lanes();
bool padded_sobol_lanes_available();  // padded_sobol_lanes() != none
// Whether the processor runs `lanes`.
bool padded_sobol_lanes_supported(SobolLanes lanes);

// camera_samples / bounce_samples of SamplerKind::sobol on padded_sobol_lanes(), which
// must be available; and on given lanes, which the processor must run (not none).
CameraSamples padded_sobol_camera_block_lanes(const PixelSample& sample, bool lens);
BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& sample, int depth, unsigned needs);
CameraSamples padded_sobol_camera_block_lanes(SobolLanes lanes, const PixelSample& sample, bool lens);
BounceSamples padded_sobol_bounce_block_lanes(SobolLanes lanes, const PixelSample& sample, int depth, unsigned needs);

// Camera blocks of several samples and whole bounce blocks of several path vertices, each
// written to *out: the block padded_sobol_camera_block_lanes(PixelSample{seed, pixel, …,
// sample_index}, lens) or padded_sobol_bounce_block_lanes(…, depth, kNeedAllBounceSamples)
// gives, for the seed and pixel whose padded_sobol_pixel_key (padded_sobol.h) is
// pixel_key. The same bits; with AVX-512, two blocks per pass, one in each half of 512-bit
// registers. On padded_sobol_lanes(), which must be available, or on given lanes, which
// the processor must run.
struct CameraBlockRequest {
  std::uint64_t pixel_key;
  std::uint32_t sample_index;
  CameraSamples* out;
};
void padded_sobol_camera_blocks_lanes(std::span<const CameraBlockRequest> requests, bool lens);
void padded_sobol_camera_blocks_lanes(SobolLanes lanes, std::span<const CameraBlockRequest> requests, bool lens);
struct BounceBlockRequest {
  std::uint64_t pixel_key;
  std::uint32_t sample_index;
  std::int32_t depth;
  BounceSamples* out;
};
void padded_sobol_bounce_blocks_lanes(std::span<const BounceBlockRequest> requests);
void padded_sobol_bounce_blocks_lanes(SobolLanes lanes, std::span<const BounceBlockRequest> requests);

}  // namespace prism
