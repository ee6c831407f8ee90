// The samplers behind --sampler: the fixed dimension layout, per-pixel nets of the padded
// Sobol' sampler for any aligned run of samples (so no spp needs to be known), the
// cross-pixel nets of the blue-noise (zsobol) layers, and uniformity.
#include "prism/sampling/pixel_sampler.h"

#include <gtest/gtest.h>

#include <vector>

#include "prism/core/sample_stream.h"
#include "prism/sampling/owen_scrambling.h"
#include "prism/sampling/padded_sobol.h"
#include "prism/sampling/padded_sobol_lanes.h"
#include "prism/sampling/sobol.h"
#include "prism/sampling/zsobol_index.h"
#include "support/chi_square.h"

namespace prism {
namespace {

std::uint32_t bits(float u) { return static_cast<std::uint32_t>(static_cast<double>(u) * 0x1p32); }

// Same criterion as sobol_test.cpp, on floats (24 significant bits suffice for m ≤ 12).
void expect_same(Vec2f a, Vec2f b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
}

bool is_zero_m_2_net(const std::vector<Vec2f>& points, int m) {
  const std::size_t n = std::size_t{1} << m;
  if (points.size() != n) return false;
  for (int k = 0; k <= m; ++k) {
    std::vector<int> count(n, 0);
    for (const Vec2f& p : points) {
      const std::uint64_t a = k == 0 ? 0 : bits(p.x) >> (32 - k);
      const std::uint64_t b = m - k == 0 ? 0 : bits(p.y) >> (32 - (m - k));
      if (++count[(a << (m - k)) | b] > 1) return false;
    }
  }
  return true;
}

TEST(PixelSampler, ParsesAndNamesEverySampler) {
  for (SamplerKind k : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol})
    EXPECT_EQ(parse_sampler(sampler_name(k)), k);
  EXPECT_FALSE(parse_sampler("halton"));
  EXPECT_FALSE(parse_sampler(""));
}

TEST(PixelSampler, BlocksFollowTheFixedDimensionLayout) {
  for (SamplerKind k : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol}) {
    const PixelSample s{11, 9 * 64 + 5, 64, 37};
    const CameraSamples c = camera_samples(k, s);
    expect_same(c.pixel_jitter, sample_2d(k, s, 0));
    expect_same(c.lens, sample_2d(k, s, 2));
    // The wavelength number keeps more bits (double); a float request truncates to 24.
    EXPECT_NEAR(c.wavelength, sample_1d(k, s, 4), 0x1p-24);
    // Without a lens (pinhole) the other numbers are the same and the lens's are not drawn.
    const CameraSamples pinhole = camera_samples(k, s, false);
    expect_same(pinhole.pixel_jitter, c.pixel_jitter);
    EXPECT_EQ(pinhole.wavelength, c.wavelength);
    expect_same(pinhole.lens, Vec2f(0.0f, 0.0f));
    for (int depth : {0, 3}) {
      const std::uint32_t base = 5 + 7 * static_cast<std::uint32_t>(depth);
      const BounceSamples b = bounce_samples(k, s, depth);
      EXPECT_EQ(b.light_select, sample_1d(k, s, base));
      expect_same(b.light, sample_2d(k, s, base + 1));
      EXPECT_EQ(b.lobe, sample_1d(k, s, base + 3));
      expect_same(b.direction, sample_2d(k, s, base + 4));
      EXPECT_EQ(b.roulette, sample_1d(k, s, base + 6));
    }
  }
}

TEST(PixelSampler, SobolIsItsDefiningComposition) {
  // pixel_sampler.h's definition, written out with the plain building blocks: index =
  // NUS(sample, low), x = NUS(sobol_0(index), high), y = NUS(sobol_1(index), high of the
  // rehash). The sampler computes it with the bit reversals cancelled; the bits must agree.
  for (std::uint64_t seed : {0ull, 7ull})
    for (std::uint32_t pixel : {0u, 1u, 65535u})
      for (std::uint32_t sample : {0u, 1u, 2u, 3u, 17u, 1000u, 0x12345678u})
        for (std::uint32_t dimension : {0u, 4u, 5u, 9u, 60u}) {
          const std::uint64_t pixel_key = mix64(mix64(seed ^ 0x736f626f6c5eedull) + pixel);
          const std::uint64_t h = mix64(pixel_key + 0x9e3779b97f4a7c15ull * (dimension + 1ull));
          const std::uint32_t index = nested_uniform_scramble(sample, static_cast<std::uint32_t>(h));
          const std::uint32_t x = nested_uniform_scramble(sobol_sample_bits(index, 0), static_cast<std::uint32_t>(h >> 32));
          const std::uint32_t y =
              nested_uniform_scramble(sobol_sample_bits(index, 1), static_cast<std::uint32_t>(mix64(h) >> 32));
          const PixelSample s{seed, pixel, 65536, sample};
          const Vec2f u = sample_2d(SamplerKind::sobol, s, dimension);
          EXPECT_EQ(u.x, bits_to_unit_float(x));
          EXPECT_EQ(u.y, bits_to_unit_float(y));
          EXPECT_EQ(sample_1d(SamplerKind::sobol, s, dimension), bits_to_unit_float(x));
          if (dimension == kWavelengthDimension) {
            EXPECT_EQ(camera_samples(SamplerKind::sobol, s).wavelength, x * 0x1p-32);  // double: all 32 bits
          }
        }
}

TEST(PixelSampler, BounceBlocksDrawOnlyTheNumbersAskedFor) {
  // A partial block must give exactly the full block's numbers in the fields it asks for
  // (the image may not depend on which branches a vertex takes) and 0 elsewhere.
  for (SamplerKind k : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol})
    for (int depth : {0, 2, 7}) {
      const PixelSample s{3, 2 * 64 + 7, 64, 41};
      const BounceSamples full = bounce_samples(k, s, depth);
      for (unsigned needs = 0; needs <= kNeedAllBounceSamples; ++needs) {
        const BounceSamples b = bounce_samples(k, s, depth, needs);
        const bool select = needs & kNeedLightSelect, light = needs & kNeedLightPoint, lobe = needs & kNeedLobe,
                   direction = needs & kNeedDirection, roulette = needs & kNeedRoulette;
        EXPECT_EQ(b.light_select, select ? full.light_select : 0.0f);
        expect_same(b.light, light ? full.light : Vec2f(0.0f, 0.0f));
        EXPECT_EQ(b.lobe, lobe ? full.lobe : 0.0f);
        expect_same(b.direction, direction ? full.direction : Vec2f(0.0f, 0.0f));
        EXPECT_EQ(b.roulette, roulette ? full.roulette : 0.0f);
      }
    }
}

TEST(PixelSampler, OnlyNeededIsWhatAPartialBlockDraws) {
  // The integrator draws whole blocks ahead of shading and hands each vertex only_needed()
  // of it: that must be exactly what asking bounce_samples for the partial block gives.
  for (SamplerKind k : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol})
    for (std::uint32_t sample : {0u, 41u, 0x9e3779b9u}) {
      const PixelSample s{3, 5 * 64 + 1, 64, sample};
      for (unsigned needs = 0; needs <= kNeedAllBounceSamples; ++needs) {
        const BounceSamples a = only_needed(bounce_samples(k, s, 3), needs), b = bounce_samples(k, s, 3, needs);
        EXPECT_EQ(a.light_select, b.light_select);
        expect_same(a.light, b.light);
        EXPECT_EQ(a.lobe, b.lobe);
        expect_same(a.direction, b.direction);
        EXPECT_EQ(a.roulette, b.roulette);
      }
    }
}

// padded_sobol_lanes.h's blocks on `lanes` against the scalar requests (sample_1d/sample_2d,
// which never take the lanes), over seeds, pixels, sample indices with every bit in play,
// depths and every partial block; the camera block with and without a lens.
void expect_lanes_draw_the_scalar_bits(SobolLanes lanes) {
  SCOPED_TRACE(lanes == SobolLanes::avx512 ? "AVX-512 lanes" : "AVX2 lanes");
  std::uint64_t state = 1;
  const auto next = [&] { return static_cast<std::uint32_t>((state = mix64(state)) >> 32); };
  for (int trial = 0; trial < 300; ++trial) {
    const PixelSample s{next() | (std::uint64_t{next()} << 32), next() % 65536, 256, trial < 20 ? next() % 64 : next()};
    const CameraSamples c = padded_sobol_camera_block_lanes(lanes, s, true);
    expect_same(c.pixel_jitter, sample_2d(SamplerKind::sobol, s, kPixelJitterDimension));
    expect_same(c.lens, sample_2d(SamplerKind::sobol, s, kLensDimension));
    EXPECT_NEAR(c.wavelength, sample_1d(SamplerKind::sobol, s, kWavelengthDimension), 0x1p-24);
    EXPECT_EQ(bits_to_unit_float(static_cast<std::uint32_t>(c.wavelength * 0x1p32)),
              sample_1d(SamplerKind::sobol, s, kWavelengthDimension));
    const CameraSamples pinhole = padded_sobol_camera_block_lanes(lanes, s, false);
    expect_same(pinhole.pixel_jitter, c.pixel_jitter);
    expect_same(pinhole.lens, Vec2f(0.0f, 0.0f));
    EXPECT_EQ(pinhole.wavelength, c.wavelength);
    const int depth = static_cast<int>(next() % 12);
    const std::uint32_t base = kFirstBounceDimension + kDimensionsPerBounce * static_cast<std::uint32_t>(depth);
    for (unsigned needs = 0; needs <= kNeedAllBounceSamples; ++needs) {
      const BounceSamples b = padded_sobol_bounce_block_lanes(lanes, s, depth, needs);
      EXPECT_EQ(b.light_select, needs & kNeedLightSelect ? sample_1d(SamplerKind::sobol, s, base) : 0.0f);
      expect_same(b.light, needs & kNeedLightPoint ? sample_2d(SamplerKind::sobol, s, base + 1) : Vec2f(0.0f, 0.0f));
      EXPECT_EQ(b.lobe, needs & kNeedLobe ? sample_1d(SamplerKind::sobol, s, base + 3) : 0.0f);
      expect_same(b.direction, needs & kNeedDirection ? sample_2d(SamplerKind::sobol, s, base + 4) : Vec2f(0.0f, 0.0f));
      EXPECT_EQ(b.roulette, needs & kNeedRoulette ? sample_1d(SamplerKind::sobol, s, base + 6) : 0.0f);
    }
  }
}

TEST(PixelSampler, SobolLanesDrawTheScalarBits) {
  bool any = false;
  for (const SobolLanes lanes : {SobolLanes::avx2, SobolLanes::avx512}) {
    if (!padded_sobol_lanes_supported(lanes)) continue;
    expect_lanes_draw_the_scalar_bits(lanes);
    any = true;
  }
  if (!any) GTEST_SKIP() << "this processor runs no lanes";
}

// padded_sobol_camera_blocks_lanes and padded_sobol_bounce_blocks_lanes against the scalar
// requests (the wavelength number against the single camera block, which the test above
// ties to them): batches of every length up to nine (AVX-512 pairs the blocks, so an odd
// one is left over), each block with its own seed, pixel, sample index and depth, so that
// a pair's halves never share a key.
TEST(PixelSampler, SobolBlockBatchesDrawTheScalarBits) {
  bool any = false;
  std::uint64_t state = 7;
  const auto next = [&] { return static_cast<std::uint32_t>((state = mix64(state)) >> 32); };
  for (const SobolLanes lanes : {SobolLanes::avx2, SobolLanes::avx512}) {
    if (!padded_sobol_lanes_supported(lanes)) continue;
    SCOPED_TRACE(lanes == SobolLanes::avx512 ? "AVX-512 lanes" : "AVX2 lanes");
    any = true;
    for (int trial = 0; trial < 60; ++trial) {
      const std::size_t count = static_cast<std::size_t>(trial % 10);
      std::vector<PixelSample> samples(count);
      std::vector<BounceSamples> blocks(count);
      std::vector<BounceBlockRequest> requests(count);
      for (std::size_t k = 0; k < count; ++k) {
        samples[k] = {next() | (std::uint64_t{next()} << 32), next() % 65536, 256, k % 2 == 0 ? next() % 64 : next()};
        requests[k] = {padded_sobol_pixel_key(samples[k].seed, samples[k].pixel_index), samples[k].sample_index,
                       static_cast<std::int32_t>(next() % 12), &blocks[k]};
      }
      padded_sobol_bounce_blocks_lanes(lanes, requests);
      for (const bool lens : {true, false}) {
        std::vector<CameraSamples> cameras(count);
        std::vector<CameraBlockRequest> camera_requests(count);
        for (std::size_t k = 0; k < count; ++k) camera_requests[k] = {requests[k].pixel_key, samples[k].sample_index, &cameras[k]};
        padded_sobol_camera_blocks_lanes(lanes, camera_requests, lens);
        for (std::size_t k = 0; k < count; ++k) {
          expect_same(cameras[k].pixel_jitter, sample_2d(SamplerKind::sobol, samples[k], kPixelJitterDimension));
          expect_same(cameras[k].lens,
                      lens ? sample_2d(SamplerKind::sobol, samples[k], kLensDimension) : Vec2f(0.0f, 0.0f));
          EXPECT_EQ(cameras[k].wavelength, padded_sobol_camera_block_lanes(lanes, samples[k], lens).wavelength);
        }
      }
      for (std::size_t k = 0; k < count; ++k) {
        const PixelSample& s = samples[k];
        const std::uint32_t base = kFirstBounceDimension + kDimensionsPerBounce * static_cast<std::uint32_t>(requests[k].depth);
        EXPECT_EQ(blocks[k].light_select, sample_1d(SamplerKind::sobol, s, base));
        expect_same(blocks[k].light, sample_2d(SamplerKind::sobol, s, base + 1));
        EXPECT_EQ(blocks[k].lobe, sample_1d(SamplerKind::sobol, s, base + 3));
        expect_same(blocks[k].direction, sample_2d(SamplerKind::sobol, s, base + 4));
        EXPECT_EQ(blocks[k].roulette, sample_1d(SamplerKind::sobol, s, base + 6));
      }
    }
  }
  if (!any) GTEST_SKIP() << "this processor runs no lanes";
}

TEST(PixelSampler, SobolLanesAreTheWidestSupported) {
  // What the renderer takes at `--simd auto`.
  const SobolLanes widest = padded_sobol_lanes_supported(SobolLanes::avx512) ? SobolLanes::avx512
                            : padded_sobol_lanes_supported(SobolLanes::avx2) ? SobolLanes::avx2
                                                                             : SobolLanes::none;
  EXPECT_EQ(padded_sobol_lanes(), widest);
  EXPECT_EQ(padded_sobol_lanes_available(), widest != SobolLanes::none);
}

TEST(PixelSampler, SobolRunsOfSamplesArePerPixelNetsWhateverTheirLength) {
  // Progressive rendering: samples [j·2^m, (j+1)·2^m) of a pixel are a net in every 2D
  // request, for every m — a render stopped or split anywhere on such a boundary is
  // stratified without the sampler knowing the final spp.
  for (std::uint32_t pixel : {0u, 1u, 4097u})
    for (std::uint32_t dimension : {0u, 2u, 6u, 9u, 5u + 7u * 5u + 1u})
      for (int m = 1; m <= 10; ++m)
        for (std::uint32_t run : {0u, 1u, 3u}) {
          std::vector<Vec2f> points;
          for (std::uint32_t i = 0; i < (1u << m); ++i)
            points.push_back(sample_2d(SamplerKind::sobol, PixelSample{5, pixel, 65536, (run << m) + i}, dimension));
          EXPECT_TRUE(is_zero_m_2_net(points, m)) << "pixel " << pixel << " dim " << dimension << " m " << m;
        }
}

TEST(PixelSampler, ZSobolTilesOfPixelsAreNetsInEverySample) {
  // Blue-noise layers: for one sample index, the pixels of an aligned 2^k × 2^k tile hold
  // a (0,2k,2)-net in every 2D request and one point in each of the 4^k strata of every 1D
  // request (the wavelength dimension included: the first pass is stratified across pixels).
  for (std::uint32_t sample : {0u, 1u, 17u})
    for (int k = 1; k <= 4; ++k)
      for (std::uint32_t tile : {0u, 3u}) {
        const std::uint32_t side = 1u << k, x0 = tile * side, y0 = 2 * tile * side;
        for (std::uint32_t dimension : {0u, 2u, 6u, 9u}) {
          std::vector<Vec2f> points;
          std::vector<int> strata(std::size_t{1} << (2 * k), 0);
          for (std::uint32_t y = y0; y < y0 + side; ++y)
            for (std::uint32_t x = x0; x < x0 + side; ++x) {
              const PixelSample s{5, y * 1000 + x, 1000, sample};
              points.push_back(sample_2d(SamplerKind::zsobol, s, dimension));
              ++strata[bits(sample_1d(SamplerKind::zsobol, s, dimension + 2)) >> (32 - 2 * k)];
            }
          EXPECT_TRUE(is_zero_m_2_net(points, 2 * k)) << "sample " << sample << " k " << k << " dim " << dimension;
          for (int c : strata) EXPECT_EQ(c, 1) << "sample " << sample << " k " << k << " dim " << dimension + 2;
        }
      }
}

TEST(PixelSampler, ZSobolDigitPermutationKeepsAlignedBlocks) {
  for (std::uint32_t seed : {1u, 99u})
    for (int k = 1; k <= 4; ++k) {
      const std::uint32_t block = 0x1234u << (2 * k), size = 1u << (2 * k);
      std::vector<int> seen(size, 0);
      for (std::uint32_t i = 0; i < size; ++i) {
        const std::uint32_t j = permute_base4_digits(block + i, seed);
        EXPECT_EQ(j >> (2 * k), permute_base4_digits(block, seed) >> (2 * k));
        ++seen[j & (size - 1)];
      }
      for (int c : seen) EXPECT_EQ(c, 1);
    }
}

TEST(PixelSampler, EverySamplerIsUniformPerPixel) {
  // One pixel's numbers over its samples, 2D histogram 16×16, 100 expected per cell:
  // each sampler must be uniform in a bounce dimension (Šidák over the 3 samplers).
  constexpr int kBins = 16, kSamples = 25600;
  for (SamplerKind k : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol}) {
    std::vector<double> observed(kBins * kBins, 0.0);
    for (int i = 0; i < kSamples; ++i) {
      const Vec2f u = sample_2d(k, PixelSample{2, 4 * 640 + 3, 640, static_cast<std::uint32_t>(i)}, 5 + 7 * 2 + 4);
      observed[static_cast<std::size_t>(static_cast<int>(u.x * kBins) * kBins + static_cast<int>(u.y * kBins))] += 1;
    }
    const std::vector<double> expected(kBins * kBins, double(kSamples) / (kBins * kBins));
    const test::ChiSquareResult r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, test::sidak_alpha(1e-3, 3)) << sampler_name(k) << ": " << r.message;
  }
}

}  // namespace
}  // namespace prism
