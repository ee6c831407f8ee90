#pragma once
// Render settings for direct-lighting tests: an 8×8 film, one scattering event (max depth
// 1), the given transport, light estimator, samples per pixel and seed.
#include <cstdint>

#include "prism/render/renderer.h"

namespace prism::test {

inline RenderSettings direct_light_settings(TransportKind kind, LightEstimator estimator, int spp,
                                            std::uint64_t seed) {
  RenderSettings s;
  s.width = s.height = 8;
  s.samples_per_pixel = spp;
  s.seed = seed;
  s.transport.kind = kind;
  s.path.max_depth = 1;
  s.path.estimator = estimator;
  return s;
}

}  // namespace prism::test
