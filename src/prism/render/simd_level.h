#pragma once
// How much SIMD the renderer may use (`prism render --simd`): a speed setting only. Every
// level renders the same image bit for bit (PlainDiffuseLanes and SamplerLanes tests), so
// it is not part of a render's fingerprint; the lower levels exist to compare the fast
// paths against the plain ones and to run on processors without the wider instructions.
//
//   automatic  the widest the processor runs (the default)
//   avx512     the sampler's AVX-512 lanes, shading in eight AVX2 lanes
//   avx2       the sampler's AVX2 lanes, shading in eight AVX2 lanes
//   sse2       the scalar sampler, shading in four SSE2 lanes
//   scalar     the scalar sampler, every hit shaded alone
#include <string>
#include <string_view>
#include <vector>

#include "prism/sampling/sobol_lanes.h"

namespace prism {

enum class SimdLevel { automatic, avx512, avx2, sse2, scalar };

std::string_view simd_level_name(SimdLevel level);
// Exact names as listed above ("auto" for automatic). Unknown: UsageError listing them.
SimdLevel parse_simd_level(std::string_view name);
std::vector<std::string> simd_level_names();
// Whether this processor runs the level's instructions (automatic, sse2, scalar: always).
bool simd_level_supported(SimdLevel level);
// Throws UsageError naming the missing instructions where the processor does not run it.
void require_simd_level(SimdLevel level);

// What a supported level means for each fast path.
SobolLanes sampler_lanes(SimdLevel level);
int shading_lane_width(SimdLevel level);  // hits shaded together: 8 (AVX2), 4 (SSE2) or 0 (alone)

}  // namespace prism
