#include "prism/sampling/padded_sobol_lanes.h"

#include "prism/core/env_flag.h"
#include "prism/sampling/padded_sobol.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PRISM_PADDED_SOBOL_LANES 1
#endif

namespace prism {

#if PRISM_PADDED_SOBOL_LANES
namespace {

// The blocks are compiled twice from padded_sobol_lane_blocks.inc, under a target pragma
// each: for AVX2, and for AVX-512 (DQ and VL: a 64-bit multiply in one instruction) with
// GFNI (a byte's bits reversed in one affine transform). The AVX-512 blocks run the same
// integer operations on the same 256-bit registers, so their bits are the AVX2 blocks'
// (pixel_sampler_test compares both with the scalar requests). GCC takes a target pragma,
// Clang (the sanitizer builds) a target attribute applied to every function of the region.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2 {

// AVX2 multiplies 32 × 32 → 64 bits only:
// the low 64 bits of a·c are lo(a)·lo(c) + ((hi(a)·lo(c) + lo(a)·hi(c)) << 32), all
// modulo 2^64 as the scalar multiply is.
inline __m256i multiply_low64_lanes(__m256i a, std::uint64_t c) {
  const __m256i c_low = _mm256_set1_epi64x(static_cast<long long>(c & 0xffffffffu));
  const __m256i c_high = _mm256_set1_epi64x(static_cast<long long>(c >> 32));
  const __m256i cross = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), c_low), _mm256_mul_epu32(a, c_high));
  return _mm256_add_epi64(_mm256_mul_epu32(a, c_low), _mm256_slli_epi64(cross, 32));
}

// Each byte's bits in reverse order, a nibble at a time through a 16-entry table.
inline __m256i reverse_bits_in_bytes(__m256i x) {
  const __m256i nibble_reversed = _mm256_setr_epi8(0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3,
                                                   0xb, 0x7, 0xf,  //
                                                   0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3,
                                                   0xb, 0x7, 0xf);
  const __m256i low_nibbles = _mm256_set1_epi8(0x0f);
  const __m256i low = _mm256_and_si256(x, low_nibbles);
  const __m256i high = _mm256_and_si256(_mm256_srli_epi16(x, 4), low_nibbles);
  // A byte's reversed low nibble becomes its high nibble: the table's values are below 16,
  // so a 16-bit shift by 4 carries nothing into the next byte.
  return _mm256_or_si256(_mm256_slli_epi16(_mm256_shuffle_epi8(nibble_reversed, low), 4),
                         _mm256_shuffle_epi8(nibble_reversed, high));
}

#include "prism/sampling/padded_sobol_lane_blocks.inc"

}  // namespace avx2
#if defined(__clang__)
#pragma clang attribute pop
#pragma clang attribute push(__attribute__((target("avx2,avx512f,avx512dq,avx512vl,gfni"))), apply_to = function)
#else
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx2,avx512f,avx512dq,avx512vl,gfni")
#endif
namespace avx512 {

// vpmullq: the low 64 bits of each product, as the scalar multiply.
inline __m256i multiply_low64_lanes(__m256i a, std::uint64_t c) {
  return _mm256_mullo_epi64(a, _mm256_set1_epi64x(static_cast<long long>(c)));
}

// Each byte's bits in reverse order, by an affine transform over GF(2) whose matrix has
// row i = bit (7 − i): the bytes 0x01, 0x02, …, 0x80 from the low byte of the 64-bit
// constant up (Intel SDM, GF2P8AFFINEQB).
inline __m256i reverse_bits_in_bytes(__m256i x) {
  return _mm256_gf2p8affine_epi64_epi8(x, _mm256_set1_epi64x(static_cast<long long>(0x8040201008040201ull)), 0);
}

#include "prism/sampling/padded_sobol_lane_blocks.inc"

}  // namespace avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

bool supported(SobolLanes lanes) {
  __builtin_cpu_init();  // this may run before any other static initialiser
  switch (lanes) {
    case SobolLanes::none: return true;
    case SobolLanes::avx2: return __builtin_cpu_supports("avx2");
    case SobolLanes::avx512:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") &&
             __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("gfni");
  }
  return false;
}

SobolLanes detect_lanes() {
  // PRISM_SAMPLER_SCALAR=1 takes the scalar path, PRISM_SAMPLER_AVX2=1 the AVX2 lanes where
  // the processor has more (to compare them on one machine).
  if (env_flag("PRISM_SAMPLER_SCALAR")) return SobolLanes::none;
  if (!env_flag("PRISM_SAMPLER_AVX2") && supported(SobolLanes::avx512)) return SobolLanes::avx512;
  return supported(SobolLanes::avx2) ? SobolLanes::avx2 : SobolLanes::none;
}

const SobolLanes kLanes = detect_lanes();

}  // namespace

SobolLanes padded_sobol_lanes() { return kLanes; }
bool padded_sobol_lanes_available() { return kLanes != SobolLanes::none; }
bool padded_sobol_lanes_supported(SobolLanes lanes) { return supported(lanes); }

CameraSamples padded_sobol_camera_block_lanes(SobolLanes lanes, const PixelSample& s, bool lens) {
  if (lanes == SobolLanes::avx512) return avx512::camera_block(s, lens);
  return avx2::camera_block(s, lens);
}

BounceSamples padded_sobol_bounce_block_lanes(SobolLanes lanes, const PixelSample& s, int depth, unsigned needs) {
  if (lanes == SobolLanes::avx512) return avx512::bounce_block(s, depth, needs);
  return avx2::bounce_block(s, depth, needs);
}

#else

SobolLanes padded_sobol_lanes() { return SobolLanes::none; }
bool padded_sobol_lanes_available() { return false; }
bool padded_sobol_lanes_supported(SobolLanes lanes) { return lanes == SobolLanes::none; }

// Not reached: the scalar path is taken.
CameraSamples padded_sobol_camera_block_lanes(SobolLanes, const PixelSample& s, bool lens) {
  return camera_samples(SamplerKind::sobol, s, lens);
}
BounceSamples padded_sobol_bounce_block_lanes(SobolLanes, const PixelSample& s, int depth, unsigned needs) {
  return bounce_samples(SamplerKind::sobol, s, depth, needs);
}

#endif

CameraSamples padded_sobol_camera_block_lanes(const PixelSample& s, bool lens) {
  return padded_sobol_camera_block_lanes(padded_sobol_lanes(), s, lens);
}

BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& s, int depth, unsigned needs) {
  return padded_sobol_bounce_block_lanes(padded_sobol_lanes(), s, depth, needs);
}

}  // namespace prism
