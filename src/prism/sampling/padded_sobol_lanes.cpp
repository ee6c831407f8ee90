#include "prism/sampling/padded_sobol_lanes.h"

#include <cstdlib>

#include "prism/sampling/padded_sobol.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PRISM_PADDED_SOBOL_LANES 1
#endif

namespace prism {

#if PRISM_PADDED_SOBOL_LANES
namespace {

#define PRISM_AVX2 __attribute__((target("avx2")))

// owen_scrambling.h's laine_karras_permutation in every lane (vpmulld keeps the low 32
// bits of each product, as the scalar multiply does).
PRISM_AVX2 inline __m256i laine_karras_lanes(__m256i x, __m256i seed) {
  x = _mm256_add_epi32(x, seed);
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(0x6c50b47c)));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(static_cast<int>(0xb82f1e52u))));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(static_cast<int>(0xc7afe638u))));
  x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(static_cast<int>(0x8d22f6e6u))));
  return x;
}

// sobol.h's reverse_bits_32 in every lane: the lane's bytes in reverse order (one byte
// shuffle), then each byte's bits, a nibble at a time through a 16-entry table.
PRISM_AVX2 inline __m256i reverse_bits_lanes(__m256i x) {
  const __m256i byte_order = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,  //
                                              3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  const __m256i nibble_reversed = _mm256_setr_epi8(0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3,
                                                   0xb, 0x7, 0xf,  //
                                                   0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3,
                                                   0xb, 0x7, 0xf);
  const __m256i low_nibbles = _mm256_set1_epi8(0x0f);
  x = _mm256_shuffle_epi8(x, byte_order);
  const __m256i low = _mm256_and_si256(x, low_nibbles);
  const __m256i high = _mm256_and_si256(_mm256_srli_epi16(x, 4), low_nibbles);
  // A byte's reversed low nibble becomes its high nibble: the table's values are below 16,
  // so a 16-bit shift by 4 carries nothing into the next byte.
  return _mm256_or_si256(_mm256_slli_epi16(_mm256_shuffle_epi8(nibble_reversed, low), 4),
                         _mm256_shuffle_epi8(nibble_reversed, high));
}

// sobol.h's sobol_dimension1_reversed_bits in every lane, in closed form. Column j of
// dimension 1's generator matrix holds row j of Pascal's triangle mod 2 (m_j = Σ_k C(j,k)
// 2^k, sobol.h), so bit m of the reversed point is the XOR of the index bits j with C(j, m)
// odd, which by Lucas' theorem are the j whose set bits include m's: a sum over supersets
// of bit positions, five shift-and-XOR steps, one per bit of a position.
PRISM_AVX2 inline __m256i superset_step(__m256i v, int shift, std::uint32_t positions) {
  return _mm256_xor_si256(v, _mm256_and_si256(_mm256_srli_epi32(v, shift), _mm256_set1_epi32(static_cast<int>(positions))));
}
PRISM_AVX2 inline __m256i sobol_dimension1_reversed_lanes(__m256i i) {
  i = superset_step(i, 1, 0x55555555u);
  i = superset_step(i, 2, 0x33333333u);
  i = superset_step(i, 4, 0x0f0f0f0fu);
  i = superset_step(i, 8, 0x00ff00ffu);
  return superset_step(i, 16, 0x0000ffffu);
}

// The scrambled points of eight lanes: lane k shuffles the sample index with
// shuffle_seeds[k]; where bit k of `dimension1` is set it takes Sobol' dimension 1 of that
// index, otherwise dimension 0, and scrambles it with scramble_seeds[k]. As floats in
// [0, 1) (bits_to_unit_float), and as bits.
struct LanePoints {
  alignas(32) float u[8];
  __m256i bits;
};
template <int dimension1>
PRISM_AVX2 inline LanePoints scrambled_points(std::uint32_t sample_index, __m256i shuffle_seeds, __m256i scramble_seeds) {
  const __m256i index =
      reverse_bits_lanes(laine_karras_lanes(reverse_bits_lanes(_mm256_set1_epi32(static_cast<int>(sample_index))), shuffle_seeds));
  const __m256i point = _mm256_blend_epi32(index, sobol_dimension1_reversed_lanes(index), dimension1);
  LanePoints p;
  p.bits = reverse_bits_lanes(laine_karras_lanes(point, scramble_seeds));
  // The top 24 bits, exact in float (below 2^24, so the signed conversion is right).
  _mm256_store_ps(p.u, _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_srli_epi32(p.bits, 8)), _mm256_set1_ps(0x1p-24f)));
  return p;
}

// sample_stream.h's mix64 in four 64-bit lanes. AVX2 multiplies 32 × 32 → 64 bits only:
// the low 64 bits of a·c are lo(a)·lo(c) + ((hi(a)·lo(c) + lo(a)·hi(c)) << 32), all
// modulo 2^64 as the scalar multiply is.
PRISM_AVX2 inline __m256i multiply_low64_lanes(__m256i a, std::uint64_t c) {
  const __m256i c_low = _mm256_set1_epi64x(static_cast<long long>(c & 0xffffffffu));
  const __m256i c_high = _mm256_set1_epi64x(static_cast<long long>(c >> 32));
  const __m256i cross = _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), c_low), _mm256_mul_epu32(a, c_high));
  return _mm256_add_epi64(_mm256_mul_epu32(a, c_low), _mm256_slli_epi64(cross, 32));
}
PRISM_AVX2 inline __m256i mix64_lanes(__m256i z) {
  z = multiply_low64_lanes(_mm256_xor_si256(z, _mm256_srli_epi64(z, 30)), 0xbf58476d1ce4e5b9ull);
  z = multiply_low64_lanes(_mm256_xor_si256(z, _mm256_srli_epi64(z, 27)), 0x94d049bb133111ebull);
  return _mm256_xor_si256(z, _mm256_srli_epi64(z, 31));
}

// padded_sobol_request_hash of four dimensions `base + offsets[k]` in the four 64-bit
// lanes, where bit k of `asked` is set; 0 (whose seeds are all 0, as mix64(0) = 0) elsewhere.
PRISM_AVX2 inline __m256i request_hash_lanes(std::uint64_t pixel_key, std::uint32_t base, __m256i offsets, int asked) {
  constexpr std::uint64_t kStep = kPaddedSobolDimensionStep;
  // key + step·(base + offset + 1) = (key + step·(base + 1)) + step·offset, modulo 2^64.
  const __m256i keys = _mm256_add_epi64(_mm256_set1_epi64x(static_cast<long long>(pixel_key + kStep * (base + 1ull))),
                                        multiply_low64_lanes(offsets, kStep));
  const __m256i lane_bits = _mm256_setr_epi64x(1, 2, 4, 8);
  const __m256i asked_lanes = _mm256_cmpeq_epi64(_mm256_and_si256(_mm256_set1_epi64x(asked), lane_bits), lane_bits);
  return _mm256_and_si256(mix64_lanes(keys), asked_lanes);
}

// The low (shuffle) or high (scramble) 32-bit halves of the 64-bit lanes of a and b, as
// the eight 32-bit lanes a0 a1 a2 a3 b0 b1 b2 b3.
PRISM_AVX2 inline __m256i halves_lanes(__m256i a, __m256i b, bool high) {
  const __m256i pick = high ? _mm256_setr_epi32(1, 3, 5, 7, 1, 3, 5, 7) : _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
  return _mm256_permute2x128_si256(_mm256_permutevar8x32_epi32(a, pick), _mm256_permutevar8x32_epi32(b, pick), 0x20);
}

bool detect_lanes() {
  // PRISM_SAMPLER_SCALAR=1 takes the scalar path (to compare the two on one machine).
  if (const char* scalar = std::getenv("PRISM_SAMPLER_SCALAR"); scalar && *scalar && *scalar != '0') return false;
  __builtin_cpu_init();  // this may run before any other static initialiser
  return __builtin_cpu_supports("avx2");
}

const bool kLanes = detect_lanes();

}  // namespace

bool padded_sobol_lanes_available() { return kLanes; }

// Lanes: 0 pixel jitter x, 1 lens x, 2 wavelength, 3 jitter y, 4 lens y. The three
// requests are hashed in three 64-bit lanes, and rehashed there for the second axes.
PRISM_AVX2 CameraSamples padded_sobol_camera_block_lanes(const PixelSample& s, bool lens) {
  const std::uint64_t key = padded_sobol_pixel_key(s.seed, s.pixel_index);
  static_assert(kPixelJitterDimension == 0 && kLensDimension == 2 && kWavelengthDimension == 4);
  // Requests jitter, lens, wavelength, none.
  const __m256i hash = request_hash_lanes(key, kPixelJitterDimension, _mm256_setr_epi64x(0, 2, 4, 0), lens ? 0b111 : 0b101);
  const __m256i rehash = mix64_lanes(hash);
  // Shuffles: jitter, lens, wavelength, jitter, lens, then 0 (lane 3 of hash is 0).
  const __m256i shuffle_seeds = _mm256_permutevar8x32_epi32(hash, _mm256_setr_epi32(0, 2, 4, 0, 2, 6, 6, 6));
  // Scrambles: the three high halves, then the rehashes' of jitter and lens (y axes), then 0.
  const __m256i scramble_seeds =
      _mm256_blend_epi32(_mm256_permutevar8x32_epi32(hash, _mm256_setr_epi32(1, 3, 5, 7, 7, 7, 7, 7)),
                         _mm256_permutevar8x32_epi32(rehash, _mm256_setr_epi32(7, 7, 7, 1, 3, 7, 7, 7)), 0b00011000);
  const LanePoints p = scrambled_points<0b11000>(s.sample_index, shuffle_seeds, scramble_seeds);
  CameraSamples c;
  c.pixel_jitter = {p.u[0], p.u[3]};
  if (lens) c.lens = {p.u[1], p.u[4]};
  c.wavelength = static_cast<std::uint32_t>(_mm256_extract_epi32(p.bits, 2)) * 0x1p-32;  // all 32 bits
  return c;
}

// Lanes: 0 light select, 1 light x, 2 lobe, 3 direction x, 4 roulette, 5 light y,
// 6 direction y. A request not asked for is not hashed: its lanes run on zero seeds and are
// not read. The requests are hashed in two vectors of four 64-bit lanes laid out as the
// eight lanes are (light and direction twice), and the second one's lanes 5 and 6 rehashed
// for the second axes.
PRISM_AVX2 BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& s, int depth, unsigned needs) {
  const std::uint64_t key = padded_sobol_pixel_key(s.seed, s.pixel_index);
  const std::uint32_t base = kFirstBounceDimension + kDimensionsPerBounce * static_cast<std::uint32_t>(depth);
  const int select = needs & kNeedLightSelect ? 1 : 0, light = needs & kNeedLightPoint ? 1 : 0,
            lobe = needs & kNeedLobe ? 1 : 0, direction = needs & kNeedDirection ? 1 : 0,
            roulette = needs & kNeedRoulette ? 1 : 0;
  // Dimension offsets in the block: select 0, light 1, lobe 3, direction 4, roulette 6.
  const __m256i first = request_hash_lanes(key, base, _mm256_setr_epi64x(0, 1, 3, 4),
                                           select | light << 1 | lobe << 2 | direction << 3);
  const __m256i second = request_hash_lanes(key, base, _mm256_setr_epi64x(6, 1, 4, 0), roulette | light << 1 | direction << 2);
  const __m256i second_axes = _mm256_blend_epi32(second, mix64_lanes(second), 0b00111100);
  const LanePoints p = scrambled_points<0b1100000>(s.sample_index, halves_lanes(first, second, false),
                                                   halves_lanes(first, second_axes, true));
  BounceSamples b;
  if (needs & kNeedLightSelect) b.light_select = p.u[0];
  if (needs & kNeedLightPoint) b.light = {p.u[1], p.u[5]};
  if (needs & kNeedLobe) b.lobe = p.u[2];
  if (needs & kNeedDirection) b.direction = {p.u[3], p.u[6]};
  if (needs & kNeedRoulette) b.roulette = p.u[4];
  return b;
}

#else

bool padded_sobol_lanes_available() { return false; }

CameraSamples padded_sobol_camera_block_lanes(const PixelSample& s, bool lens) {
  return camera_samples(SamplerKind::sobol, s, lens);  // not reached: the scalar path is taken
}
BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& s, int depth, unsigned needs) {
  return bounce_samples(SamplerKind::sobol, s, depth, needs);
}

#endif

}  // namespace prism
