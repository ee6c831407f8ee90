// BSDF sample + eval per call, 4 wavelengths, random outgoing directions in the upper
// hemisphere: Lambert, rough GGX conductor (VNDF sampling) and rough dielectric.
#include <benchmark/benchmark.h>

#include <vector>

#include "prism/bsdf/bsdf.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/warps.h"

namespace {

using prism::Vec2f;
using prism::Vec3f;
constexpr int kN = 4;

std::vector<Vec3f> outgoing_directions() {
  prism::Pcg32 rng(3, 4);
  std::vector<Vec3f> wo(4096);
  for (auto& w : wo) w = prism::sample_cosine_hemisphere(Vec2f(rng.next_float(), rng.next_float()));
  return wo;
}

prism::bsdf::Bsdf<kN> make_bsdf(int kind) {
  using namespace prism::bsdf;
  const auto ggx = MicrofacetDistribution::isotropic(MicrofacetType::ggx, 0.3f);
  if (kind == 0) return {Lambertian<kN>{prism::color::SampledSpectrum<kN>(0.7f)}};
  if (kind == 1)
    return {RoughConductor<kN>{ggx, ConductorFresnel<kN>::schlick(prism::color::SampledSpectrum<kN>(0.9f))}};
  Dielectric<kN> d;
  d.distribution = ggx;
  return {d};
}

void BM_BsdfSample(benchmark::State& state) {
  const auto bsdf = make_bsdf(static_cast<int>(state.range(0)));
  const auto wo = outgoing_directions();
  prism::Pcg32 rng(5, 6);
  std::size_t i = 0;
  for (auto _ : state) {
    auto s = bsdf.sample(wo[i++ & 4095], rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BsdfSample)->Arg(0)->Arg(1)->Arg(2)->ArgName("lambert0_conductor1_dielectric2");

// The diffuse warp alone (concentric disk + Malley), on precomputed uniform numbers.
void BM_SampleCosineHemisphere(benchmark::State& state) {
  prism::Pcg32 rng(7, 8);
  std::vector<Vec2f> u(4096);
  for (auto& v : u) v = Vec2f(rng.next_float(), rng.next_float());
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(prism::sample_cosine_hemisphere(u[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SampleCosineHemisphere);

void BM_BsdfEvalPdf(benchmark::State& state) {
  const auto bsdf = make_bsdf(static_cast<int>(state.range(0)));
  const auto wo = outgoing_directions();
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec3f& a = wo[i & 4095];
    const Vec3f& b = wo[(i * 7 + 1) & 4095];
    ++i;
    benchmark::DoNotOptimize(bsdf.eval(a, b));
    benchmark::DoNotOptimize(bsdf.pdf(a, b));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BsdfEvalPdf)->Arg(0)->Arg(1)->Arg(2)->ArgName("lambert0_conductor1_dielectric2");

}  // namespace
