#include "prism/sampling/padded_sobol_lanes.h"

#include <stdexcept>

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
// (pixel_sampler_test compares both with the scalar requests); two bounce blocks at once
// run them on the two halves of 512-bit registers (BW: byte shuffles of 512 bits). GCC takes a target pragma,
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
#pragma clang attribute push(__attribute__((target("avx2,avx512f,avx512dq,avx512vl,avx512bw,gfni"))), apply_to = function)
#else
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx2,avx512f,avx512dq,avx512vl,avx512bw,gfni")
// GCC 12 takes the AVX-512 intrinsics' undefined pass-through operand
// (_mm512_undefined_epi32, a self-initialised variable) for an uninitialised read once
// they are inlined: a false -Wmaybe-uninitialized (GCC bug 105593, fixed in GCC 13).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
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

// Two bounce blocks at once, every number asked for: block a in the low 256 bits of each
// 512-bit register (the low eight 32-bit lanes, the low four 64-bit ones), block b in the
// high, each half taking bounce_block_of_key's operations on its own lanes, in its order;
// so the same bits, in half the instructions.
inline __m512i halves_of(std::uint64_t a, std::uint64_t b) {
  return _mm512_inserti64x4(_mm512_castsi256_si512(_mm256_set1_epi64x(static_cast<long long>(a))),
                            _mm256_set1_epi64x(static_cast<long long>(b)), 1);
}
inline __m512i mix64_pair(__m512i z) {
  z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 30)), _mm512_set1_epi64(static_cast<long long>(0xbf58476d1ce4e5b9ull)));
  z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 27)), _mm512_set1_epi64(static_cast<long long>(0x94d049bb133111ebull)));
  return _mm512_xor_si512(z, _mm512_srli_epi64(z, 31));
}
inline __m512i reverse_bits_pair(__m512i x) {
  const __m512i byte_order = _mm512_broadcast_i32x4(_mm_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
  return _mm512_gf2p8affine_epi64_epi8(_mm512_shuffle_epi8(x, byte_order),
                                       _mm512_set1_epi64(static_cast<long long>(0x8040201008040201ull)), 0);
}
inline __m512i laine_karras_pair(__m512i x, __m512i seed) {
  x = _mm512_add_epi32(x, seed);
  x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(0x6c50b47c)));
  x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(static_cast<int>(0xb82f1e52u))));
  x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(static_cast<int>(0xc7afe638u))));
  x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(static_cast<int>(0x8d22f6e6u))));
  return x;
}
inline __m512i superset_step_pair(__m512i v, unsigned shift, std::uint32_t positions) {
  return _mm512_xor_si512(v, _mm512_and_si512(_mm512_srli_epi32(v, shift), _mm512_set1_epi32(static_cast<int>(positions))));
}
inline __m512i sobol_dimension1_reversed_pair(__m512i i) {
  i = superset_step_pair(i, 1, 0x55555555u);
  i = superset_step_pair(i, 2, 0x33333333u);
  i = superset_step_pair(i, 4, 0x0f0f0f0fu);
  i = superset_step_pair(i, 8, 0x00ff00ffu);
  return superset_step_pair(i, 16, 0x0000ffffu);
}
// Dimension offsets o0 … o3 times the dimension step, in both halves (request_hash_lanes'
// offsets). A function of the region, not a lambda: a lambda does not take the region's
// target, and would pass the register through memory.
inline __m512i dimension_steps_pair(std::uint64_t o0, std::uint64_t o1, std::uint64_t o2, std::uint64_t o3) {
  constexpr std::uint64_t kStep = kPaddedSobolDimensionStep;
  const auto step = [](std::uint64_t o) { return static_cast<long long>(o * kStep); };
  return _mm512_setr_epi64(step(o0), step(o1), step(o2), step(o3), step(o0), step(o1), step(o2), step(o3));
}

// scrambled_points (padded_sobol_lane_blocks.inc) of two blocks: sample index a's in the low
// half, b's in the high, `dimension1` (one block's lanes) in each half.
struct PairPoints {
  alignas(64) float u[16];
  alignas(64) std::uint32_t bits[16];
};
template <unsigned dimension1>
PairPoints scrambled_points_pair(std::uint32_t a, std::uint32_t b, __m512i shuffle_seeds, __m512i scramble_seeds) {
  const __m512i sample_index = _mm512_inserti32x8(_mm512_set1_epi32(static_cast<int>(a)),
                                                  _mm256_set1_epi32(static_cast<int>(b)), 1);
  const __m512i index = reverse_bits_pair(laine_karras_pair(reverse_bits_pair(sample_index), shuffle_seeds));
  const __m512i point =
      _mm512_mask_blend_epi32(dimension1 | dimension1 << 8, index, sobol_dimension1_reversed_pair(index));
  const __m512i bits = reverse_bits_pair(laine_karras_pair(point, scramble_seeds));
  PairPoints p;
  _mm512_store_ps(p.u, _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_srli_epi32(bits, 8)), _mm512_set1_ps(0x1p-24f)));
  _mm512_store_si512(p.bits, bits);
  return p;
}

void bounce_block_pair(const BounceBlockRequest& a, const BounceBlockRequest& b) {
  constexpr std::uint64_t kStep = kPaddedSobolDimensionStep;
  const auto block_key = [](const BounceBlockRequest& r) {
    const std::uint32_t base = kFirstBounceDimension + kDimensionsPerBounce * static_cast<std::uint32_t>(r.depth);
    return r.pixel_key + kStep * (base + 1ull);
  };
  const __m512i keys = halves_of(block_key(a), block_key(b));
  // request_hash_lanes' dimension offsets, times the step: first select 0, light 1, lobe 3,
  // direction 4; second roulette 6, light 1, direction 4, and a lane asked for nothing (0).
  const __m512i first = mix64_pair(_mm512_add_epi64(keys, dimension_steps_pair(0, 1, 3, 4)));
  const __m512i second =
      _mm512_maskz_mov_epi64(0b01110111, mix64_pair(_mm512_add_epi64(keys, dimension_steps_pair(6, 1, 4, 0))));
  const __m512i second_axes = _mm512_mask_blend_epi32(0x3c3c, second, mix64_pair(second));
  // halves_lanes in each half: the low (shuffle) or high (scramble) 32 bits of first's four
  // 64-bit lanes, then of the other operand's four.
  const __m512i low_halves = _mm512_setr_epi32(0, 2, 4, 6, 16, 18, 20, 22, 8, 10, 12, 14, 24, 26, 28, 30);
  const __m512i high_halves = _mm512_add_epi32(low_halves, _mm512_set1_epi32(1));
  const __m512i shuffle_seeds = _mm512_permutex2var_epi32(first, low_halves, second);
  const __m512i scramble_seeds = _mm512_permutex2var_epi32(first, high_halves, second_axes);
  const PairPoints p = scrambled_points_pair<0b1100000>(a.sample_index, b.sample_index, shuffle_seeds, scramble_seeds);
  for (int h = 0; h < 2; ++h) {
    const float* v = p.u + 8 * h;
    BounceSamples& out = *(h == 0 ? a : b).out;
    out.light_select = v[0];
    out.light = {v[1], v[5]};
    out.lobe = v[2];
    out.direction = {v[3], v[6]};
    out.roulette = v[4];
  }
}

// camera_block_of_key for two samples at once, in the halves of 512-bit registers as
// bounce_block_pair.
void camera_block_pair(const CameraBlockRequest& a, const CameraBlockRequest& b, bool lens) {
  constexpr std::uint64_t kStep = kPaddedSobolDimensionStep;
  static_assert(kPixelJitterDimension == 0 && kLensDimension == 2 && kWavelengthDimension == 4);
  // request_hash_lanes: jitter, lens, wavelength and a lane asked for nothing, in each half.
  const __m512i keys = _mm512_add_epi64(halves_of(a.pixel_key + kStep, b.pixel_key + kStep), dimension_steps_pair(0, 2, 4, 0));
  const __m512i hash = _mm512_maskz_mov_epi64(lens ? 0b01110111 : 0b01010101, mix64_pair(keys));
  const __m512i rehash = mix64_pair(hash);
  const __m512i shuffle_seeds =
      _mm512_permutexvar_epi32(_mm512_setr_epi32(0, 2, 4, 0, 2, 6, 6, 6, 8, 10, 12, 8, 10, 14, 14, 14), hash);
  const __m512i scramble_seeds = _mm512_mask_blend_epi32(
      0x1818, _mm512_permutexvar_epi32(_mm512_setr_epi32(1, 3, 5, 7, 7, 7, 7, 7, 9, 11, 13, 15, 15, 15, 15, 15), hash),
      _mm512_permutexvar_epi32(_mm512_setr_epi32(7, 7, 7, 1, 3, 7, 7, 7, 15, 15, 15, 9, 11, 15, 15, 15), rehash));
  const PairPoints p = scrambled_points_pair<0b11000>(a.sample_index, b.sample_index, shuffle_seeds, scramble_seeds);
  for (int h = 0; h < 2; ++h) {
    const float* v = p.u + 8 * h;
    CameraSamples& out = *(h == 0 ? a : b).out;
    out.pixel_jitter = {v[0], v[3]};
    out.lens = lens ? Vec2f(v[1], v[4]) : Vec2f(0.0f, 0.0f);
    out.wavelength = p.bits[8 * h + 2] * 0x1p-32;  // all 32 bits
  }
}

void camera_blocks(std::span<const CameraBlockRequest> requests, bool lens) {
  std::size_t k = 0;
  for (; k + 1 < requests.size(); k += 2) camera_block_pair(requests[k], requests[k + 1], lens);
  if (k < requests.size()) *requests[k].out = camera_block_of_key(requests[k].pixel_key, requests[k].sample_index, lens);
}

void bounce_blocks(std::span<const BounceBlockRequest> requests) {
  std::size_t k = 0;
  for (; k + 1 < requests.size(); k += 2) bounce_block_pair(requests[k], requests[k + 1]);
  if (k < requests.size()) {
    const BounceBlockRequest& r = requests[k];
    *r.out = bounce_block_of_key(r.pixel_key, r.sample_index, r.depth, kNeedAllBounceSamples);
  }
}

}  // namespace avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif

bool supported(SobolLanes lanes) {
  __builtin_cpu_init();  // this may run before any other static initialiser
  switch (lanes) {
    case SobolLanes::none: return true;
    case SobolLanes::avx2: return __builtin_cpu_supports("avx2");
    case SobolLanes::avx512:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") &&
             __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") &&
             __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("gfni");
  }
  return false;
}

SobolLanes detect_lanes() {
  if (supported(SobolLanes::avx512)) return SobolLanes::avx512;
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

void padded_sobol_camera_blocks_lanes(SobolLanes lanes, std::span<const CameraBlockRequest> requests, bool lens) {
  if (lanes == SobolLanes::avx512) return avx512::camera_blocks(requests, lens);
  for (const CameraBlockRequest& r : requests) *r.out = avx2::camera_block_of_key(r.pixel_key, r.sample_index, lens);
}

void padded_sobol_bounce_blocks_lanes(SobolLanes lanes, std::span<const BounceBlockRequest> requests) {
  if (lanes == SobolLanes::avx512) return avx512::bounce_blocks(requests);
  for (const BounceBlockRequest& r : requests)
    *r.out = avx2::bounce_block_of_key(r.pixel_key, r.sample_index, r.depth, kNeedAllBounceSamples);
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
void padded_sobol_camera_blocks_lanes(SobolLanes, std::span<const CameraBlockRequest>, bool) {
  throw std::logic_error("padded_sobol_camera_blocks_lanes: no lanes in this build");
}
void padded_sobol_bounce_blocks_lanes(SobolLanes, std::span<const BounceBlockRequest>) {
  throw std::logic_error("padded_sobol_bounce_blocks_lanes: no lanes in this build");
}

#endif

CameraSamples padded_sobol_camera_block_lanes(const PixelSample& s, bool lens) {
  return padded_sobol_camera_block_lanes(padded_sobol_lanes(), s, lens);
}

BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& s, int depth, unsigned needs) {
  return padded_sobol_bounce_block_lanes(padded_sobol_lanes(), s, depth, needs);
}

void padded_sobol_camera_blocks_lanes(std::span<const CameraBlockRequest> requests, bool lens) {
  padded_sobol_camera_blocks_lanes(padded_sobol_lanes(), requests, lens);
}

void padded_sobol_bounce_blocks_lanes(std::span<const BounceBlockRequest> requests) {
  padded_sobol_bounce_blocks_lanes(padded_sobol_lanes(), requests);
}

}  // namespace prism
