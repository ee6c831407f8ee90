#pragma once
// Progressive driver: renders whole passes of one sample per pixel until the sample
// target, the time limit or a cancellation request ends the render.
#include <atomic>
#include <cstdint>
#include <functional>

#include "prism/render/film.h"
#include "prism/render/path_tracer.h"
#include "prism/scene/scene.h"

namespace prism {

struct RenderSettings {
  int width = 512;
  int height = 512;
  int samples_per_pixel = 64;
  double time_limit_seconds = 0.0;  // 0: no limit
  std::uint64_t seed = 0;
  int threads = 0;                  // 0: all hardware threads
  PathTracerSettings path;
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
  int passes_done = 0;  // complete passes; a cancelled pass may have left some pixels one sample ahead
  double elapsed_seconds = 0.0;
  std::uint64_t invalid_samples = 0;  // NaN/Inf radiance discarded, never written to the film
  StopReason stop_reason = StopReason::completed;
};

using ProgressCallback = std::function<void(const RenderProgress&)>;

// Renders `scene`. The film depends only on the scene, the settings' sizes, spp, seed
// and path settings, never on `threads` or timing (for complete passes). `cancel` may be
// set from another thread or a signal handler; the render then stops within one row.
RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const ProgressCallback& on_pass = {}, const std::atomic<bool>* cancel = nullptr);

}  // namespace prism
