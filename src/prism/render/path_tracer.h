#pragma once
// The minimal unidirectional path tracer of the foundation: Lambertian surfaces,
// cosine-weighted BSDF sampling, next-event estimation to area lights, multiple
// importance sampling with the power heuristic (Veach 1997, ch. 9), Russian roulette.
// It is replaced by the wavefront integrator; keep it small and correct.
#include <cstdint>
#include <vector>

#include "prism/accel/embree_accel.h"
#include "prism/core/pcg32.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/scene.h"

namespace prism {

// How direct light is estimated. All three converge to the same image; mis has the
// lowest variance. nee_only and bsdf_only exist to test that claim.
enum class LightEstimator { mis, nee_only, bsdf_only };

struct PathTracerSettings {
  int max_depth = 8;               // scattering events; 1 = direct lighting only
  int russian_roulette_depth = 3;  // roulette starts after this many bounces
  LightEstimator estimator = LightEstimator::mis;
};

struct PathContext {
  const Scene& scene;
  const EmbreeAccel& accel;
  const LightSampler& lights;
  PathTracerSettings settings;
  std::vector<Vec3f> emitted_radiance;  // per material, linear Rec.709
};

// Radiance arriving along `ray` (film RGB).
Vec3f trace_path(const PathContext& context, Ray ray, Pcg32& rng);

}  // namespace prism
