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

PRISM_AVX2 inline int lane_seed(std::uint32_t seed) { return static_cast<int>(seed); }

bool detect_lanes() {
  // PRISM_SAMPLER_SCALAR=1 takes the scalar path (to compare the two on one machine).
  if (const char* scalar = std::getenv("PRISM_SAMPLER_SCALAR"); scalar && *scalar && *scalar != '0') return false;
  __builtin_cpu_init();  // this may run before any other static initialiser
  return __builtin_cpu_supports("avx2");
}

const bool kLanes = detect_lanes();

}  // namespace

bool padded_sobol_lanes_available() { return kLanes; }

// Lanes: 0 pixel jitter x, 1 lens x, 2 wavelength, 3 jitter y, 4 lens y.
PRISM_AVX2 CameraSamples padded_sobol_camera_block_lanes(const PixelSample& s, bool lens) {
  const std::uint64_t key = padded_sobol_pixel_key(s.seed, s.pixel_index);
  const std::uint64_t jitter = padded_sobol_request_hash(key, kPixelJitterDimension);
  const std::uint64_t lens_hash = lens ? padded_sobol_request_hash(key, kLensDimension) : 0;
  const std::uint64_t wavelength = padded_sobol_request_hash(key, kWavelengthDimension);
  const int jitter_shuffle = lane_seed(padded_sobol_shuffle_seed(jitter)),
            lens_shuffle = lane_seed(padded_sobol_shuffle_seed(lens_hash));
  const LanePoints p = scrambled_points<0b11000>(
      s.sample_index,
      _mm256_setr_epi32(jitter_shuffle, lens_shuffle, lane_seed(padded_sobol_shuffle_seed(wavelength)), jitter_shuffle,
                        lens_shuffle, 0, 0, 0),
      _mm256_setr_epi32(lane_seed(padded_sobol_x_seed(jitter)), lane_seed(padded_sobol_x_seed(lens_hash)),
                        lane_seed(padded_sobol_x_seed(wavelength)), lane_seed(padded_sobol_y_seed(jitter)),
                        lens ? lane_seed(padded_sobol_y_seed(lens_hash)) : 0, 0, 0, 0));
  CameraSamples c;
  c.pixel_jitter = {p.u[0], p.u[3]};
  if (lens) c.lens = {p.u[1], p.u[4]};
  c.wavelength = static_cast<std::uint32_t>(_mm256_extract_epi32(p.bits, 2)) * 0x1p-32;  // all 32 bits
  return c;
}

// Lanes: 0 light select, 1 light x, 2 lobe, 3 direction x, 4 roulette, 5 light y,
// 6 direction y. A request not asked for is not hashed: its lanes run on zero seeds and are
// not read.
PRISM_AVX2 BounceSamples padded_sobol_bounce_block_lanes(const PixelSample& s, int depth, unsigned needs) {
  const std::uint64_t key = padded_sobol_pixel_key(s.seed, s.pixel_index);
  const std::uint32_t base = kFirstBounceDimension + kDimensionsPerBounce * static_cast<std::uint32_t>(depth);
  const auto hash = [&](unsigned need, std::uint32_t offset) -> std::uint64_t {
    return needs & need ? padded_sobol_request_hash(key, base + offset) : 0;
  };
  const std::uint64_t select = hash(kNeedLightSelect, 0), light = hash(kNeedLightPoint, 1), lobe = hash(kNeedLobe, 3),
                      direction = hash(kNeedDirection, 4), roulette = hash(kNeedRoulette, 6);
  const int light_shuffle = lane_seed(padded_sobol_shuffle_seed(light)),
            direction_shuffle = lane_seed(padded_sobol_shuffle_seed(direction));
  const LanePoints p = scrambled_points<0b1100000>(
      s.sample_index,
      _mm256_setr_epi32(lane_seed(padded_sobol_shuffle_seed(select)), light_shuffle, lane_seed(padded_sobol_shuffle_seed(lobe)),
                        direction_shuffle, lane_seed(padded_sobol_shuffle_seed(roulette)), light_shuffle, direction_shuffle,
                        0),
      _mm256_setr_epi32(lane_seed(padded_sobol_x_seed(select)), lane_seed(padded_sobol_x_seed(light)),
                        lane_seed(padded_sobol_x_seed(lobe)), lane_seed(padded_sobol_x_seed(direction)),
                        lane_seed(padded_sobol_x_seed(roulette)),
                        needs & kNeedLightPoint ? lane_seed(padded_sobol_y_seed(light)) : 0,
                        needs & kNeedDirection ? lane_seed(padded_sobol_y_seed(direction)) : 0, 0));
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
