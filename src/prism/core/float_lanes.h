#pragma once
// Floats in lanes: one value per path, for code that takes several paths through the same
// scalar steps at once (the wavefront integrator's plain diffuse hits,
// render/wavefront_plain_lanes.cpp). A lane's result is the scalar code's, bit for bit,
// where the operations come in the same order:
// - + − × ÷ and the square root are IEEE single precision and correctly rounded, in a lane
//   as in a scalar register (addps … sqrtps, vaddps … vsqrtps against addss … sqrtss);
// - there is no fused multiply-add (neither the build nor the AVX2 region enables FMA, and
//   GCC contracts nothing it cannot emit);
// - min, max and the selects are the comparisons std::min, std::max and `c ? a : b` make,
//   not minps / maxps, which differ from them on signed zeros and NaNs.
// Two widths, the same operations (float_lanes_ops.inc): lanes::sse2, four lanes in SSE2
// (every x86-64), and lanes::avx2, eight lanes in AVX2, compiled for AVX2 alone (a target
// pragma or attribute region), so only code that has checked the processor may call it.
// GCC's vector extensions, which Clang has too.
#include <cmath>
#include <cstdint>

#include "prism/core/target_region.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PRISM_FLOAT_LANES_AVX2 1
#endif

namespace prism::lanes {

namespace sse2 {
inline constexpr int kWidth = 4;
using Float = float __attribute__((vector_size(16)));
using Mask = std::int32_t __attribute__((vector_size(16)));  // a comparison's: all bits set where true
inline Float sqrt(Float x) {
#if defined(__SSE2__)
  return reinterpret_cast<Float>(_mm_sqrt_ps(reinterpret_cast<__m128>(x)));
#else
  for (int k = 0; k < kWidth; ++k) x[k] = std::sqrt(x[k]);
  return x;
#endif
}
#include "prism/core/float_lanes_ops.inc"
}  // namespace sse2

#if PRISM_FLOAT_LANES_AVX2
PRISM_TARGET_REGION_BEGIN("avx2")
namespace avx2 {
inline constexpr int kWidth = 8;
using Float = float __attribute__((vector_size(32)));
using Mask = std::int32_t __attribute__((vector_size(32)));
inline Float sqrt(Float x) { return reinterpret_cast<Float>(_mm256_sqrt_ps(reinterpret_cast<__m256>(x))); }
#include "prism/core/float_lanes_ops.inc"
}  // namespace avx2
PRISM_TARGET_REGION_END
// Whether this processor runs lanes::avx2.
inline bool avx2_supported() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}
#else
inline bool avx2_supported() { return false; }
#endif

}  // namespace prism::lanes
