#include "prism/sampling/pixel_sampler.h"

#include "prism/core/pcg32.h"
#include "prism/core/sample_stream.h"
#include "prism/sampling/owen_scrambling.h"
#include "prism/sampling/padded_sobol.h"
#include "prism/sampling/padded_sobol_lanes.h"
#include "prism/sampling/sobol.h"
#include "prism/sampling/zsobol_index.h"

namespace prism {
namespace {

// Each sampler answers 1D and 2D requests for a dimension as 32-bit fractions (PCG: as
// floats/doubles of its own stream).
struct IndependentDimensions {
  std::uint64_t key, sample_key;
  explicit IndependentDimensions(const PixelSample& s)
      : key(mix64(mix64(s.seed ^ 0x9e3779b97f4a7c15ull) + s.pixel_index)), sample_key(mix64(key + s.sample_index)) {}
  // One PCG32 stream per (seed, pixel, sample, dimension): make_sample_stream's, with the
  // request's first dimension mixed into the starting state.
  Pcg32 stream(std::uint32_t dimension) const { return Pcg32(mix64(sample_key + dimension), key); }
  float get1d(std::uint32_t dimension) const { return stream(dimension).next_float(); }
  double get1d_double(std::uint32_t dimension) const { return stream(dimension).next_double(); }
  Vec2f get2d(std::uint32_t dimension) const {
    Pcg32 rng = stream(dimension);
    const float u = rng.next_float();
    return {u, rng.next_float()};
  }
};

// Padded Sobol' with Burley's (2020) shuffled, Owen-scrambled index, all seeds per
// (seed, pixel, dimension) (padded_sobol.h). Where the processor has AVX2, the blocks are
// drawn by padded_sobol_lanes.h instead, with the same bits.
struct PaddedSobolDimensions {
  std::uint64_t pixel_key;
  std::uint32_t reversed_sample_index;
  explicit PaddedSobolDimensions(const PixelSample& s)
      : pixel_key(padded_sobol_pixel_key(s.seed, s.pixel_index)), reversed_sample_index(reverse_bits_32(s.sample_index)) {}
  std::uint64_t request_hash(std::uint32_t dimension) const { return padded_sobol_request_hash(pixel_key, dimension); }
  static std::uint32_t low(std::uint64_t h) { return padded_sobol_shuffle_seed(h); }
  static std::uint32_t high(std::uint64_t h) { return padded_sobol_x_seed(h); }
  std::uint32_t shuffled_index(std::uint64_t h) const {
    return reverse_bits_32(laine_karras_permutation(reversed_sample_index, low(h)));
  }
  static std::uint32_t x_bits(std::uint32_t index, std::uint64_t h) {
    return reverse_bits_32(laine_karras_permutation(index, high(h)));
  }
  float get1d(std::uint32_t dimension) const {
    const std::uint64_t h = request_hash(dimension);
    return bits_to_unit_float(x_bits(shuffled_index(h), h));
  }
  double get1d_double(std::uint32_t dimension) const {
    const std::uint64_t h = request_hash(dimension);
    return x_bits(shuffled_index(h), h) * 0x1p-32;
  }
  Vec2f get2d(std::uint32_t dimension) const {
    const std::uint64_t h = request_hash(dimension);
    const std::uint32_t index = shuffled_index(h);
    const std::uint32_t y = reverse_bits_32(laine_karras_permutation(sobol_dimension1_reversed_bits(index), padded_sobol_y_seed(h)));
    return {bits_to_unit_float(x_bits(index, h)), bits_to_unit_float(y)};
  }
};

// One blue-noise layer per sample index: the Morton index of the pixel, its base-4 digits
// permuted per (seed, sample, dimension), scrambled with seeds shared by all pixels of the
// layer so that tiles keep their net property (zsobol_index.h).
struct ZSobolDimensions {
  std::uint64_t layer_key;
  std::uint32_t morton;
  explicit ZSobolDimensions(const PixelSample& s)
      : layer_key(mix64(mix64(s.seed ^ 0x7a736f626f6cull) + s.sample_index)),
        morton(morton_index_2d(s.pixel_index % s.image_width, s.pixel_index / s.image_width)) {}
  std::uint64_t request_hash(std::uint32_t dimension) const {
    return mix64(layer_key + 0x9e3779b97f4a7c15ull * (dimension + 1ull));
  }
  // The request hash's low half chooses the digit permutations; a second hash of it gives
  // the two axes' scramble seeds.
  std::uint32_t index(std::uint64_t h) const { return permute_base4_digits(morton, static_cast<std::uint32_t>(h)); }
  static std::uint32_t scramble_seed(std::uint64_t h, int axis) {
    return static_cast<std::uint32_t>(mix64(h) >> (32 * axis));
  }
  std::uint32_t x_bits(std::uint64_t h) const {
    return nested_uniform_scramble(sobol_sample_bits(index(h), 0), scramble_seed(h, 0));
  }
  float get1d(std::uint32_t dimension) const { return bits_to_unit_float(x_bits(request_hash(dimension))); }
  double get1d_double(std::uint32_t dimension) const { return x_bits(request_hash(dimension)) * 0x1p-32; }
  Vec2f get2d(std::uint32_t dimension) const {
    const std::uint64_t h = request_hash(dimension);
    const std::uint32_t i = index(h);
    return {bits_to_unit_float(nested_uniform_scramble(sobol_sample_bits(i, 0), scramble_seed(h, 0))),
            bits_to_unit_float(nested_uniform_scramble(sobol_sample_bits(i, 1), scramble_seed(h, 1)))};
  }
};

template <class Dimensions>
CameraSamples camera_block(const Dimensions& d, bool lens) {
  return {d.get2d(kPixelJitterDimension), lens ? d.get2d(kLensDimension) : Vec2f(0.0f, 0.0f),
          d.get1d_double(kWavelengthDimension)};
}

template <class Dimensions>
BounceSamples bounce_block(const Dimensions& d, int depth, unsigned needs) {
  const std::uint32_t base = kFirstBounceDimension + kDimensionsPerBounce * static_cast<std::uint32_t>(depth);
  BounceSamples b;
  if (needs & kNeedLightSelect) b.light_select = d.get1d(base);
  if (needs & kNeedLightPoint) b.light = d.get2d(base + 1);
  if (needs & kNeedLobe) b.lobe = d.get1d(base + 3);
  if (needs & kNeedDirection) b.direction = d.get2d(base + 4);
  if (needs & kNeedRoulette) b.roulette = d.get1d(base + 6);
  return b;
}

}  // namespace

std::string_view sampler_name(SamplerKind kind) {
  switch (kind) {
    case SamplerKind::independent: return "independent";
    case SamplerKind::sobol: return "sobol";
    case SamplerKind::zsobol: return "zsobol";
  }
  return "unknown";
}

std::optional<SamplerKind> parse_sampler(std::string_view name) {
  for (SamplerKind k : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol})
    if (name == sampler_name(k)) return k;
  return std::nullopt;
}

CameraSamples camera_samples(SamplerKind kind, const PixelSample& s, bool lens) {
  return camera_samples(kind, padded_sobol_lanes(), s, lens);
}

BounceSamples bounce_samples(SamplerKind kind, const PixelSample& s, int depth, unsigned needs) {
  return bounce_samples(kind, padded_sobol_lanes(), s, depth, needs);
}

CameraSamples camera_samples(SamplerKind kind, SobolLanes lanes, const PixelSample& s, bool lens) {
  switch (kind) {
    case SamplerKind::sobol:
      return lanes != SobolLanes::none ? padded_sobol_camera_block_lanes(lanes, s, lens)
                                       : camera_block(PaddedSobolDimensions{s}, lens);
    case SamplerKind::zsobol: return camera_block(ZSobolDimensions{s}, lens);
    case SamplerKind::independent: break;
  }
  return camera_block(IndependentDimensions{s}, lens);
}

BounceSamples bounce_samples(SamplerKind kind, SobolLanes lanes, const PixelSample& s, int depth, unsigned needs) {
  switch (kind) {
    case SamplerKind::sobol:
      return lanes != SobolLanes::none ? padded_sobol_bounce_block_lanes(lanes, s, depth, needs)
                                       : bounce_block(PaddedSobolDimensions{s}, depth, needs);
    case SamplerKind::zsobol: return bounce_block(ZSobolDimensions{s}, depth, needs);
    case SamplerKind::independent: break;
  }
  return bounce_block(IndependentDimensions{s}, depth, needs);
}

bool whole_bounce_blocks_are_cheap(SamplerKind kind, SobolLanes lanes) {
  return kind == SamplerKind::sobol && lanes != SobolLanes::none;
}

float sample_1d(SamplerKind kind, const PixelSample& s, std::uint32_t dimension) {
  switch (kind) {
    case SamplerKind::sobol: return PaddedSobolDimensions{s}.get1d(dimension);
    case SamplerKind::zsobol: return ZSobolDimensions{s}.get1d(dimension);
    case SamplerKind::independent: break;
  }
  return IndependentDimensions{s}.get1d(dimension);
}

Vec2f sample_2d(SamplerKind kind, const PixelSample& s, std::uint32_t dimension) {
  switch (kind) {
    case SamplerKind::sobol: return PaddedSobolDimensions{s}.get2d(dimension);
    case SamplerKind::zsobol: return ZSobolDimensions{s}.get2d(dimension);
    case SamplerKind::independent: break;
  }
  return IndependentDimensions{s}.get2d(dimension);
}

}  // namespace prism
