#pragma once
// The random numbers of one path sample, as a pure function of (seed, pixel, sample
// index, dimension): no state lives in the path, and a sample's numbers never depend on
// the thread, on the pass it is rendered in, or on how many samples the render will take
// (time-limited renders, --resume and --sample-range chunks all see the same numbers).
//
// Fixed dimension layout, so that dimension k means the same decision in every sample
// (required for low-discrepancy samplers to stratify anything):
//   0-1 pixel jitter, 2-3 lens, 4 wavelength,
//   then per bounce (depth d ≥ 0) a block of 7 at 5 + 7·d: light select, light 2D, lobe,
//   direction 2D, Russian roulette. A block is drawn whole whether or not a branch uses
//   all of it.
//   Microfacet normal mapping's two facet choices at depth d are the 2D request at
//   dimension 2^31 + 2d (sample_2d), outside the blocks, so that turning it on leaves every
//   other number as it was.
//
// Samplers:
//   independent: a PCG32 stream (O'Neill 2014) per (seed, pixel, sample, block).
//   sobol: padded Owen-scrambled Sobol' (Burley 2020): every 1D/2D request uses Sobol'
//          dimensions 0(/1) at the sample index shuffled by a nested uniform scramble
//          seeded per (seed, pixel, dimension), and the point Owen-scrambled per (seed,
//          pixel, dimension). Any aligned run of 2^m samples of a pixel is a scrambled
//          (0,m,2)-net in every 2D request, for every m — the net property needs no spp.
//   zsobol: blue-noise ordering across pixels (Ahmed & Wonka 2020; pbrt-v4's
//          ZSobolSampler). pbrt puts the sample index below the Morton digits, which
//          needs the final spp (log2 spp bits); here the bound is fixed at ONE sample per
//          layer: sample index s is layer s, in which every aligned 2^k×2^k tile of pixels
//          shares one (0,2k,2)-net of the Sobol' sequence (Morton index, base-4 digits
//          permuted per layer and dimension); layers are scrambled independently. So at
//          every spp the error is spread as blue noise and the first pass is stratified
//          across pixels (wavelengths included), but within one pixel successive samples
//          are independent: per-pixel variance is that of independent sampling.
#include <cstdint>
#include <optional>
#include <string_view>

#include "prism/core/vec.h"
#include "prism/sampling/sobol_lanes.h"

namespace prism {

enum class SamplerKind : std::uint8_t { independent, sobol, zsobol };

std::string_view sampler_name(SamplerKind kind);
std::optional<SamplerKind> parse_sampler(std::string_view name);  // nullopt for unknown names

inline constexpr std::uint32_t kPixelJitterDimension = 0;
inline constexpr std::uint32_t kLensDimension = 2;
inline constexpr std::uint32_t kWavelengthDimension = 4;
inline constexpr std::uint32_t kFirstBounceDimension = 5;
inline constexpr std::uint32_t kDimensionsPerBounce = 7;
inline constexpr std::uint32_t kFirstFacetDimension = 0x80000000u;

struct PixelSample {
  std::uint64_t seed = 0;
  std::uint32_t pixel_index = 0;  // y · image_width + x
  std::uint32_t image_width = 1;  // pixels per row: zsobol finds the pixel's (x, y) from it
  std::uint32_t sample_index = 0;
};

struct CameraSamples {
  Vec2f pixel_jitter;  // [0,1)² inside the pixel
  Vec2f lens;
  double wavelength = 0.0;  // the primary number of wavelength sampling
};

struct BounceSamples {
  float light_select = 0.0f;
  Vec2f light;
  float lobe = 0.0f;
  Vec2f direction;
  float roulette = 0.0f;
};

// Which numbers of a bounce block a vertex uses. The others are left 0 and cost nothing;
// their dimensions stay reserved, so the numbers that are drawn do not depend on the mask.
enum BounceNeeds : unsigned {
  kNeedLightPoint = 1u,  // light
  kNeedLobe = 2u,
  kNeedDirection = 4u,
  kNeedRoulette = 8u,
  kNeedLightSelect = 16u,  // light_select
  kNeedLight = kNeedLightSelect | kNeedLightPoint,
  kNeedAllBounceSamples = 31u,
};

// One switch over the sampler per block, not per number. Without `lens` (pinhole
// cameras) the lens numbers are left 0 and not drawn; their dimensions stay reserved.
// The padded Sobol' sampler's blocks are drawn on `lanes` (sobol_lanes.h; the same bits on
// every choice, which the processor must run), or without them on the widest lanes the
// processor runs (padded_sobol_lanes.h).
CameraSamples camera_samples(SamplerKind kind, const PixelSample& sample, bool lens = true);
BounceSamples bounce_samples(SamplerKind kind, const PixelSample& sample, int depth,
                             unsigned needs = kNeedAllBounceSamples);
CameraSamples camera_samples(SamplerKind kind, SobolLanes lanes, const PixelSample& sample, bool lens);
BounceSamples bounce_samples(SamplerKind kind, SobolLanes lanes, const PixelSample& sample, int depth,
                             unsigned needs);

// The numbers of a whole block that `needs` asks for, the others 0: what bounce_samples
// returns for `needs` (the integrator draws whole blocks ahead of shading, where that is
// cheaper, and hands each vertex only what it asked for).
constexpr BounceSamples only_needed(BounceSamples b, unsigned needs) {
  if (!(needs & kNeedLightSelect)) b.light_select = 0.0f;
  if (!(needs & kNeedLightPoint)) b.light = Vec2f(0.0f, 0.0f);
  if (!(needs & kNeedLobe)) b.lobe = 0.0f;
  if (!(needs & kNeedDirection)) b.direction = Vec2f(0.0f, 0.0f);
  if (!(needs & kNeedRoulette)) b.roulette = 0.0f;
  return b;
}

// Whether drawing a whole bounce block costs little more than the numbers a vertex reads:
// the padded Sobol' sampler on AVX2 or AVX-512 lanes (padded_sobol_lanes.h).
bool whole_bounce_blocks_are_cheap(SamplerKind kind, SobolLanes lanes);

// Single requests (tests, tools, and the numbers outside the blocks): dimension
// `dimension` (and `dimension + 1` for 2D) of a sample, as laid out above.
float sample_1d(SamplerKind kind, const PixelSample& sample, std::uint32_t dimension);
Vec2f sample_2d(SamplerKind kind, const PixelSample& sample, std::uint32_t dimension);

}  // namespace prism
