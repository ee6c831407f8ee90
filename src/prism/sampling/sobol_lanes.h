#pragma once
// Which SIMD lanes draw the padded Sobol' sampler's blocks (padded_sobol_lanes.h): the
// bits are the scalar path's on every choice, so it is a speed setting, not an image one.

namespace prism {

enum class SobolLanes : unsigned char {
  none,    // the scalar path
  avx2,    // AVX2
  avx512,  // AVX2 with AVX-512F/DQ/VL/BW and GFNI, on the same 256-bit registers (and
           // 512-bit ones for two bounce blocks at once, padded_sobol_bounce_blocks_lanes)
};

}  // namespace prism
