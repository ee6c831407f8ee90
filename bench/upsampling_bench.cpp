// RGB → spectrum coefficients (Jakob & Hanika 2019 table lookup), as every textured base
// colour and every environment-map radiance pays it: random colours anywhere in the
// cube, and a smooth run of sky-like colours (neighbouring lookups land in neighbouring
// cells, as along an environment map's texels).
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/color/jakob_hanika_table.h"
#include "prism/core/pcg32.h"

namespace {

std::vector<prism::Vec3d> colours(bool smooth) {
  prism::Pcg32 rng(21, 22);
  std::vector<prism::Vec3d> c(4096);
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (smooth) {
      const double t = static_cast<double>(i) / static_cast<double>(c.size());
      c[i] = {0.2 + 0.3 * t, 0.4 + 0.3 * t, 0.9 - 0.1 * t};
    } else {
      c[i] = {rng.next_float(), rng.next_float(), rng.next_float()};
    }
  }
  return c;
}

void BM_JakobHanikaLookup(benchmark::State& state) {
  const prism::color::JakobHanikaTable& table = prism::color::JakobHanikaTable::get("srgb");
  const std::vector<prism::Vec3d> c = colours(state.range(0) != 0);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(table.lookup(c[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

// 0: random colours, 1: a smooth sky gradient.
BENCHMARK(BM_JakobHanikaLookup)->Arg(0)->Arg(1);
