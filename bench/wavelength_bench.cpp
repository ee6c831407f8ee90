// Drawing a path's wavelengths (4 per path), per strategy: the integrator does this once
// per sample, and it was once the hottest function (see the cosh-lobe precomputation).
#include <benchmark/benchmark.h>

#include "prism/color/wavelength_sampling.h"
#include "prism/core/pcg32.h"

namespace {

void BM_SampleWavelengths(benchmark::State& state) {
  const auto strategy = static_cast<prism::color::WavelengthStrategy>(state.range(0));
  prism::Pcg32 rng(1, 1);
  for (auto _ : state) benchmark::DoNotOptimize(prism::color::sample_wavelengths<4>(strategy, rng.next_float()));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(std::string(prism::color::wavelength_strategy_name(strategy)));
}
BENCHMARK(BM_SampleWavelengths)->Arg(0)->Arg(1)->Arg(2)->ArgName("hero0_cosh1_cosh3_2");

}  // namespace
