// Hits on plain diffuse materials shaded several at a time: the steps shade() takes for
// such a hit (surface_interaction, then shade_surface<true>), in the same order, with the
// arithmetic on directions and points done for all the lanes at once (core/float_lanes.h)
// and the spectra, the emitter's selection and the emitters' spectra lane by lane; area
// sampled triangle lights are sampled in lanes too, other emitters by the light sampler.
// Every float is the scalar step's own operation on the same operands, so each slot ends
// with the bits shade() gives it (plain_diffuse_render_test compares whole images); the
// hits that cannot go this way (WavefrontIntegrator::shades_in_lanes) are shaded alone.
// One body (wavefront_plain_lanes_body.inc) compiled twice: four SSE2 lanes
// (shade_plain_lanes) and eight AVX2 lanes (shade_plain_lanes_avx2, which the integrator
// calls only where the processor has AVX2).
//
// Why: on the Cornell box the plain path spent most of its instructions on three-vector
// arithmetic in scalar registers (the hit's geometry, its frame, the light sample's and the
// sampled direction's coordinates, the rays' offsets); docs/performance-design.md "Plain diffuse lanes".
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "prism/core/float_lanes.h"
#include "prism/core/lane_slots.h"
#include "prism/core/target_region.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/render/wavefront_paths.h"
#include "prism/sampling/warps.h"
#include "prism/scene/triangle_light_sampling.h"

namespace prism {
namespace {

namespace plain_lanes_sse2 {
namespace ops = lanes::sse2;
#include "prism/render/wavefront_plain_lanes_helpers.inc"
}  // namespace plain_lanes_sse2

#if PRISM_FLOAT_LANES_AVX2
PRISM_TARGET_REGION_BEGIN("avx2")
namespace plain_lanes_avx2 {
namespace ops = lanes::avx2;
#include "prism/render/wavefront_plain_lanes_helpers.inc"
}  // namespace plain_lanes_avx2
PRISM_TARGET_REGION_END
#endif

}  // namespace

template <class Mode>
void WavefrontIntegrator<Mode>::shade_plain_lanes(Paths& p, const std::uint32_t* slots) const {
  namespace L = plain_lanes_sse2;
#include "prism/render/wavefront_plain_lanes_body.inc"
}

#if PRISM_FLOAT_LANES_AVX2
template <class Mode>
[[gnu::target("avx2")]] void WavefrontIntegrator<Mode>::shade_plain_lanes_avx2(Paths& p, const std::uint32_t* slots) const {
  namespace L = plain_lanes_avx2;
#include "prism/render/wavefront_plain_lanes_body.inc"
}
#endif

template void WavefrontIntegrator<SpectralMode<3>>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<SpectralMode<4>>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<SpectralMode<8>>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<RgbMode>::shade_plain_lanes(Paths&, const std::uint32_t*) const;
#if PRISM_FLOAT_LANES_AVX2
template void WavefrontIntegrator<SpectralMode<3>>::shade_plain_lanes_avx2(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<SpectralMode<4>>::shade_plain_lanes_avx2(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<SpectralMode<8>>::shade_plain_lanes_avx2(Paths&, const std::uint32_t*) const;
template void WavefrontIntegrator<RgbMode>::shade_plain_lanes_avx2(Paths&, const std::uint32_t*) const;
#endif

}  // namespace prism
