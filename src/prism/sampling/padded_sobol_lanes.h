#pragma once
// The padded Owen-scrambled Sobol' sampler's camera and bounce blocks (pixel_sampler.h,
// "sobol"; Burley 2020) with their requests side by side in the eight 32-bit lanes of one
// AVX2 register. A bounce block's five requests need five index shuffles and seven axis
// scrambles, each a Laine–Karras permutation and a bit reversal: twelve scalar chains of
// about 25 instructions, here two passes over one register (a bit reversal is a byte
// shuffle and two nibble-table lookups; Sobol' dimension 1 is computed in closed form
// instead of through byte tables). The request hashes stay scalar (padded_sobol.h), and
// only the requests a vertex asks for are hashed.
//
// The bits are exactly those of the scalar path (pixel_sampler_test compares them, and
// renders are bitwise the same). Chosen at run time: a build for plain x86-64 also runs on
// processors without AVX2, which take the scalar path.
#include "prism/sampling/pixel_sampler.h"

namespace prism {

// Whether this build and processor run the lanes (decided once, before main).
bool padded_sobol_lanes_available();

// camera_samples / bounce_samples of SamplerKind::sobol; only where
// padded_sobol_lanes_available().
CameraSamples padded_sobol_camera_block_lanes(const PixelSample& sample, bool lens);
BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& sample, int depth, unsigned needs);

}  // namespace prism
