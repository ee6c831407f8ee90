#pragma once
// Progressive driver: renders passes (a few samples of every pixel, sized to take about
// half a second) with the chosen integrator (the wavefront integrator, or the reference
// path tracer it is tested against) until the sample target, the time limit or a
// cancellation request ends the render.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/render/adaptive_sampling.h"
#include "prism/render/film.h"
#include "prism/render/image_fingerprint.h"
#include "prism/render/transport_mode.h"
#include "prism/render/wavefront_integrator.h"
#include "prism/scene/scene.h"

namespace prism {

// Which integrator renders: both estimate the same image (render/reference_path_tracer.h).
enum class IntegratorKind { wavefront, reference };
std::string_view integrator_name(IntegratorKind kind);
// "wavefront" or "reference"; anything else: UsageError listing them.
IntegratorKind parse_integrator(std::string_view name);
std::vector<std::string> integrator_names();

struct RenderSettings {
  int width = 512;
  int height = 512;
  // Sample indices first_sample .. samples_per_pixel - 1 are rendered, one pass each.
  // A plain render starts at 0; farms split the range (--sample-range) and merge.
  int samples_per_pixel = 64;
  int first_sample = 0;
  double time_limit_seconds = 0.0;  // 0: no limit
  std::uint64_t seed = 0;
  int threads = 0;                  // 0: all hardware threads
  PathSettings path;
  TransportSettings transport;
  IntegratorKind integrator = IntegratorKind::wavefront;
  int samples_per_pass = 0;         // 0: sized from the measured speed (about 0.5 s a pass)
  bool regenerate_paths = true;     // off: one wave per sample (for measuring the benefit)
  // > 0: RenderHooks::on_bounces sees the film after every this many bounces of the paths in
  // flight (progressive display of deep paths); 0: only after whole passes. Never changes
  // the image, so it is not part of the fingerprint.
  int bounces_per_pass = 0;
  AovSet aovs;                      // first-hit AOVs the film keeps (aov.h); none by default
  // Adaptive sampling (adaptive_sampling.h, --noise-threshold): off by default. When on, the
  // film also keeps the variance AOV's sums (adaptive_film_aovs), passes never straddle a
  // decision boundary, and a render whose every pixel has stopped ends early (its
  // next_sample is then samples_per_pixel: no pixel would take another sample). Not with
  // first_sample > 0 (--sample-range): ranges would decide on different samples.
  AdaptiveSamplingSettings adaptive;
  // Refuse (Error) before allocating when estimate_render_memory() exceeds this
  // (memory_estimate.h); 0: 90 % of physical memory.
  std::uint64_t memory_limit_bytes = 0;
};

// Validates ranges (sizes, spp, depth, threads); throws UsageError naming the option.
void validate_render_settings(const RenderSettings& settings);


struct RenderProgress {
  int passes_done = 0;
  int passes_target = 0;
  double elapsed_seconds = 0.0;
  double samples_per_second = 0.0;
};

enum class StopReason { completed, time_limit, cancelled };

struct RenderResult {
  Film film;
  color::ColorSpace film_space;  // working RGB, or CIE XYZ relative to E for spectral films
  int passes_done = 0;   // passes (samples per pixel) in the film, including resumed ones
  int next_sample = 0;   // the sample index the next pass would render
  double elapsed_seconds = 0.0;
  std::uint64_t invalid_samples = 0;  // NaN/Inf radiance discarded, never written to the film
  std::uint64_t rays = 0, shadow_rays = 0;
  std::uint64_t lane_shaded_hits = 0;  // of the closest hits, those shaded several at a time
  // Rays traced in camera packets (PassStatistics::camera_packet_rays): the camera rays
  // among `rays` come from these, which include the packets' lanes traced more than once.
  std::uint64_t camera_packet_rays = 0;
  std::vector<double> pass_seconds;
  std::vector<int> pass_samples;
  // Per pass: live paths at each wavefront step (PassStatistics::live_paths_per_step),
  // for measuring how full regeneration keeps the queues.
  std::vector<std::vector<std::uint32_t>> pass_live_paths;
  StopReason stop_reason = StopReason::completed;
};

using ProgressCallback = std::function<void(const RenderProgress&)>;
// Receives the film after a complete pass and the next sample index to render.
using CheckpointCallback = std::function<void(const Film& film, int next_sample)>;

struct RenderHooks {
  ProgressCallback on_pass;
  // May be set from another thread or a signal handler; the render stops after the
  // current pass, so the film always holds whole passes.
  const std::atomic<bool>* cancel = nullptr;
  // Called after a pass once checkpoint_interval_seconds have passed since the last call
  // (0: never during the render), and once more when the render ends for any reason.
  CheckpointCallback on_checkpoint;
  double checkpoint_interval_seconds = 0.0;
  // With RenderSettings::bounces_per_pass > 0: the film in the middle of a pass (every
  // pixel's completed samples), after every bounces_per_pass bounces, and the sample index
  // the pass started at. Checkpoints, cancellation and time limits still act between passes.
  CheckpointCallback on_bounces;
};

// Continues from a checkpointed film whose passes cover sample indices
// settings.first_sample .. next_sample - 1.
struct ResumeState {
  Film film;
  int next_sample = 0;
};

// Renders `scene`. The film depends only on the scene, the settings' sizes, sample range,
// seed and path settings, never on `threads`, timing, or whether it was resumed.
RenderResult render(const Scene& scene, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume = nullptr);

// The same, taking the scene over: its meshes and texels move into the prepared scene
// instead of being copied (`prism render`, which has no further use for them). The
// moved-from scene is left valid but unspecified.
RenderResult render(Scene&& scene, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume = nullptr);

// The same for a scene prepared once (prepared_scene.h): no validation of its geometry,
// flattening or BVH build per call, so interactive restarts cost only the film.
class PreparedScene;
RenderResult render(const PreparedScene& scene, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume = nullptr);

inline RenderResult render(const Scene& scene, const RenderSettings& settings,
                           const ProgressCallback& on_pass = {}, const std::atomic<bool>* cancel = nullptr) {
  RenderHooks hooks;
  hooks.on_pass = on_pass;
  hooks.cancel = cancel;
  return render(scene, settings, hooks);
}

}  // namespace prism
