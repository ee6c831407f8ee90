#pragma once
// The reference path tracer (`prism render --integrator reference`): one pixel sample at a
// time, one ray at a time, written in the order a textbook gives the algorithm (Veach 1997,
// ch. 9 and 10; pbrt-v4's PathIntegrator): unidirectional path tracing with next-event
// estimation, the power heuristic between light and BSDF sampling, and Russian roulette.
//
// It shades through the same SurfaceShading as the wavefront integrator, with the same
// scene, lights, samplers, wavelengths and film, and draws the same sample dimensions
// (sampling/pixel_sampler.h), so the two estimate the same image; tests hold the fast
// integrator to this one per pixel (tests/render/reference_path_tracer_test.cpp). It keeps
// no queues, lanes or caches: it is slow on purpose, and easy to read and to change first.
#include <cstdint>
#include <functional>
#include <optional>

#include "prism/accel/embree_accel.h"
#include "prism/render/aov.h"
#include "prism/render/color_context.h"
#include "prism/render/film.h"
#include "prism/render/surface_shading.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/sampling/pixel_sampler.h"
#include "prism/scene/camera_rays.h"
#include "prism/scene/light_sampler.h"

namespace prism {

template <class Mode>
class ReferencePathTracer {
 public:
  ReferencePathTracer(const Scene& scene, const EmbreeAccel& accel, const std::vector<MipPyramid>& mip_pyramids,
                      const LightSampler& lights, const PinholeCamera& camera, const ColorContext<Mode>& colors,
                      const PathSettings& settings, int width, int height, std::uint64_t seed);

  // Renders samples [first_sample, first_sample + count) of every pixel into `film`, each
  // pixel's in order, pixels in parallel: the image is independent of the thread count.
  // `after_bounces` (progressive display of deep paths) is not called: there is no
  // wavefront to stop in the middle of.
  // `active`: as WavefrontIntegrator::render_samples (adaptive sampling); null: every pixel.
  PassStatistics render_samples(Film& film, std::uint32_t first_sample, std::uint32_t count,
                                int bounces_per_pass = 0, const std::function<void()>* after_bounces = nullptr,
                                const std::uint8_t* active = nullptr);

 private:
  // The state a path carries from one vertex to the next.
  struct PathState {
    Spectrum<Mode> throughput{1.0f};  // β
    float eta_scale = 1.0f;           // Π η² of refractions, left out of roulette
    float cone_width = 0.0f;          // the ray cone's width at the last hit (scene units)
    float cone_spread = 0.0f;         // its spread angle (radians)
    bool previous_specular = true;    // camera rays see emitters directly, unweighted
    float previous_pdf = 0.0f;        // the BSDF sample's density that led here
    Vec3f previous_position{0.0f}, previous_normal{0.0f};
    std::optional<Spectrum<Mode>> interior_sigma;  // inside an absorbing dielectric: σ_a
  };
  struct Counts {
    std::uint64_t rays = 0, shadow_rays = 0;
  };

  // The radiance one camera sample carries to the film, and its first-hit AOVs.
  Spectrum<Mode> radiance(const PixelSample& sample, Ray ray, Wavelengths<Mode>& wl, AovSample* aovs,
                          Counts& counts) const;
  // Light from emitters a ray that left the scene reaches (environment, distant lights).
  Spectrum<Mode> escaped_radiance(const Vec3f& direction, const PathState& path, const Wavelengths<Mode>& wl) const;
  // Emission of the surface a BSDF-sampled (or camera) ray hit, MIS-weighted against light
  // sampling.
  Spectrum<Mode> emitted_radiance(const Hit& hit, const SurfaceInteraction& si, const PathState& path,
                                  const Wavelengths<Mode>& wl) const;
  // Next-event estimation: one light sample, its shadow ray traced, MIS-weighted.
  Spectrum<Mode> direct_light(const SurfaceInteraction& si, const bsdf::Bsdf<Mode::kChannels>& bsdf,
                              const std::optional<bsdf::NormalMapMicrosurface>& microsurface, const Vec3f& wo_local,
                              const BounceSamples& u, const PathState& path, const Wavelengths<Mode>& wl,
                              Counts& counts) const;

  SurfaceShading<Mode> shading_;
  const Scene& scene_;
  const EmbreeAccel& accel_;
  const LightSampler& lights_;
  const PinholeCamera& camera_;
  const ColorContext<Mode>& colors_;
  PathSettings settings_;
  int width_, height_;
  std::uint64_t seed_;
  bool use_nee_;           // light samples at non-specular vertices
  bool weight_bsdf_hits_;  // MIS between light samples and emitters found by BSDF sampling
};

}  // namespace prism
