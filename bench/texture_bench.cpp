// Texture lookups and mip pyramid builds (scene/texture_sampling.h) for a 2048² RGB image
// stored as floats and as 8-bit sRGB codes (what PNG and JPEG images keep since the codes
// are decoded at lookup): random uvs over the whole image, as incoherent bounces look
// textures up, at the finest level and between levels 2 and 3.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "prism/core/pcg32.h"
#include "prism/scene/texture_sampling.h"

namespace {

constexpr int kSize = 2048;

// A 2048² RGB image of hashed codes, kept as codes (8-bit) or as the floats they decode to.
const prism::TextureImage& image(bool eight_bit) {
  static const prism::TextureImage coded = [] {
    prism::TextureImage t;
    t.name = "bench";
    t.width = t.height = kSize;
    t.channels = 3;
    t.encoding = prism::TextureEncoding::srgb;
    prism::Pcg32 rng(3, 4);
    t.codes.resize(static_cast<std::size_t>(kSize) * kSize * 3);
    for (std::uint8_t& c : t.codes) c = static_cast<std::uint8_t>(rng.next_u32() >> 24);
    return t;
  }();
  static const prism::TextureImage floats = [] {
    prism::TextureImage t = coded;
    t.texels = coded.linear_values();
    t.codes.clear();
    return t;
  }();
  return eight_bit ? coded : floats;
}

void BM_TextureTrilinearLookup(benchmark::State& state) {
  const bool eight_bit = state.range(0) != 0;
  const float lod = static_cast<float>(state.range(1)) / 2.0f;
  const prism::MipPyramid pyramid = prism::build_mip_pyramid(image(eight_bit));
  prism::Pcg32 rng(5, 6);
  for (auto _ : state) {
    const prism::Vec2f uv{rng.next_float(), rng.next_float()};
    benchmark::DoNotOptimize(prism::sample_trilinear(pyramid, uv, lod));
  }
  state.SetLabel(eight_bit ? "8-bit sRGB codes" : "floats");
}
// (storage: 0 floats, 1 codes) × (level of detail × 2: 0, 5)
BENCHMARK(BM_TextureTrilinearLookup)->ArgsProduct({{0, 1}, {0, 5}});

void BM_TextureMipPyramidBuild(benchmark::State& state) {
  const prism::TextureImage& t = image(state.range(0) != 0);
  for (auto _ : state) benchmark::DoNotOptimize(prism::build_mip_pyramid(t));
  state.SetLabel(state.range(0) != 0 ? "8-bit sRGB codes" : "floats");
}
BENCHMARK(BM_TextureMipPyramidBuild)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
