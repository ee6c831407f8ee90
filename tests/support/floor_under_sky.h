#pragma once
// A test scene for materials whose albedo is known: one large floor of the given material
// (a JSON material object named "floor"), seen straight down through a 1° view, under a
// uniform white sky of 1 nit, so that the floor's radiance is its directional albedo at
// normal incidence.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/render/renderer.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/scene.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"

namespace prism::test {

inline Scene floor_under_white_sky(const std::string& material) {
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [)" + material + R"(],
    "meshes": [{"name": "floor", "material": "floor",
                "positions": [[-100, 0, -100], [100, 0, -100], [100, 0, 100], [-100, 0, 100]],
                "indices": [0, 2, 1, 0, 3, 2]}],
    "camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_degrees": 1},
    "environment": {"color": [1, 1, 1], "luminance_nits": 1}})",
                                   "floor.json", {}, "floor");
}

// The floor's radiance, Y of an 8×8 film's mean after one scattering event, with every
// light estimator in both transports (256 spp): each within 5σ of its film's noise, 5e-4 of
// `expected` (float accumulation, as the other furnaces) and the caller's `slack`.
inline void expect_floor_radiance(const Scene& scene, double expected, double slack, const std::string& what) {
  for (TransportKind kind : {TransportKind::rgb, TransportKind::spectral})
    for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
      const BlockEstimate e = block_estimate(render(scene, direct_light_settings(kind, est, 256, 3)).film, 0, 0, 8, 8);
      EXPECT_NEAR(e.mean.y, expected, 5.0 * std::sqrt(e.variance.y) + 5e-4 * expected + slack)
          << what << " transport " << static_cast<int>(kind) << " estimator " << static_cast<int>(est);
    }
}

}  // namespace prism::test
