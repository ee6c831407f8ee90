// The display pipeline per pixel: the ACES output transform (SDR and 1000-nit PQ) on one
// ACES2065-1 value, and the whole-image pipeline on a 256² image (per pixel).
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/color/color_space.h"
#include "prism/core/pcg32.h"
#include "prism/display/aces_output_kernel.h"
#include "prism/display/aces_output_transform.h"
#include "prism/display/display_pipeline.h"

namespace {

std::vector<prism::Vec3d> aces_values() {
  prism::Pcg32 rng(11, 12);
  std::vector<prism::Vec3d> v(4096);
  for (auto& a : v) a = {4.0 * rng.next_float(), 4.0 * rng.next_float(), 4.0 * rng.next_float()};
  return v;
}

void BM_AcesOutputTransformPixel(benchmark::State& state) {
  const auto odt = state.range(0) ? prism::display::OdtId::rec2020_pq_1000nit : prism::display::OdtId::srgb_100nit;
  const prism::display::AcesOutputTransform transform(odt);
  const auto values = aces_values();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(transform.display_nits(values[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AcesOutputTransformPixel)->Arg(0)->Arg(1)->ArgName("sdr0_pq1");

// The float block kernel the pipeline uses: film (here ACES2065-1) → normalised AP1 →
// display light and code values, per pixel, on the same 4096 values.
void BM_AcesOutputKernelPixel(benchmark::State& state) {
  const auto odt = state.range(0) ? prism::display::OdtId::rec2020_pq_1000nit : prism::display::OdtId::srgb_100nit;
  const prism::display::AcesOutputTransform transform(odt);
  prism::display::AcesKernelSettings settings;
  settings.encoding = transform.description().default_encoding;
  settings.white_nits = transform.description().white_nits;
  const prism::display::AcesOutputKernel kernel(transform, settings);
  std::vector<float> film;
  for (const auto& a : aces_values()) film.insert(film.end(), {float(a.x), float(a.y), float(a.z)});
  const std::size_t n = film.size() / 3;
  std::vector<float> cv(film.size()), nits(film.size()), code(film.size());
  for (auto _ : state) {
    kernel.normalized_ap1(film.data(), cv.data(), n);
    kernel.display(cv.data(), nullptr, nits.data(), code.data(), n);
    benchmark::DoNotOptimize(code.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}
BENCHMARK(BM_AcesOutputKernelPixel)->Arg(0)->Arg(1)->ArgName("sdr0_pq1");

void BM_DisplayPipelineImage(benchmark::State& state) {
  constexpr int kSize = 256;
  prism::ImageRgbF image{kSize, kSize, std::vector<float>(kSize * kSize * 3)};
  prism::Pcg32 rng(13, 14);
  for (float& v : image.rgb) v = 2.0f * rng.next_float();
  prism::display::DisplaySettings settings;
  settings.exposure_ev100 = 0.0;
  settings.odt = state.range(0) ? prism::display::OdtId::rec2020_pq_1000nit : prism::display::OdtId::srgb_100nit;
  const auto& srgb = prism::color::color_space("srgb");
  for (auto _ : state) benchmark::DoNotOptimize(prism::display::apply_display_pipeline(image, srgb, settings));
  state.SetItemsProcessed(state.iterations() * kSize * kSize);
}
BENCHMARK(BM_DisplayPipelineImage)->Arg(0)->Arg(1)->ArgName("sdr0_pq1")->Unit(benchmark::kMillisecond);

}  // namespace
