#include "prism/render/renderer.h"

#include <chrono>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/core/sample_stream.h"
#include "prism/scene/camera_rays.h"

namespace prism {

void validate_render_settings(const RenderSettings& s) {
  // 32768² matches the image-size limit the loaders use; beyond it the film alone needs
  // tens of gigabytes.
  constexpr int kMaxResolution = 32768;
  if (s.width < 1 || s.height < 1 || s.width > kMaxResolution || s.height > kMaxResolution)
    throw UsageError(fmt::format("resolution {}x{} is out of range (1 to {} per axis)", s.width, s.height, kMaxResolution));
  if (s.samples_per_pixel < 1) throw UsageError(fmt::format("--spp must be at least 1 (got {})", s.samples_per_pixel));
  if (s.path.max_depth < 1) throw UsageError(fmt::format("--max-depth must be at least 1 (got {})", s.path.max_depth));
  if (s.threads < 0) throw UsageError(fmt::format("--threads must be at least 1 (got {})", s.threads));
  if (!(s.time_limit_seconds >= 0.0)) throw UsageError("--time-limit must be a non-negative number of seconds");
}

RenderResult render(const Scene& scene, const RenderSettings& settings, const ProgressCallback& on_pass,
                    const std::atomic<bool>* cancel) {
  validate_render_settings(settings);
  validate_scene(scene);
  const ThreadLimit thread_limit(settings.threads);
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  const EmbreeAccel accel(scene);
  const LightSampler lights(scene);
  const PathContext context{scene, accel, lights, settings.path};
  const PinholeCamera camera(scene.camera, settings.width, settings.height);
  RenderResult result;
  result.film = Film(settings.width, settings.height);
  std::atomic<std::uint64_t> invalid{0};
  const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };

  for (int pass = 0; pass < settings.samples_per_pixel; ++pass) {
    parallel_for(static_cast<std::size_t>(settings.height), 1, [&](std::size_t row_begin, std::size_t row_end) {
      std::uint64_t local_invalid = 0;
      for (std::size_t y = row_begin; y < row_end && !cancelled(); ++y) {
        for (int x = 0; x < settings.width; ++x) {
          const std::size_t pixel = y * static_cast<std::size_t>(settings.width) + static_cast<std::size_t>(x);
          Pcg32 rng = make_sample_stream(settings.seed, pixel, static_cast<std::uint64_t>(pass));
          const float jitter_x = rng.next_float(), jitter_y = rng.next_float();
          const Ray ray = camera.generate_ray(static_cast<float>(x) + jitter_x, static_cast<float>(y) + jitter_y);
          const Vec3f L = trace_path(context, ray, rng);
          if (is_finite(L)) {
            result.film.add_sample(pixel, L);
          } else {
            ++local_invalid;
          }
        }
      }
      invalid += local_invalid;
    });
    if (cancelled()) {
      result.stop_reason = StopReason::cancelled;
      break;
    }
    result.passes_done = pass + 1;
    const double seconds = elapsed();
    if (on_pass) {
      const double samples = static_cast<double>(result.passes_done) * result.film.pixel_count();
      on_pass({result.passes_done, settings.samples_per_pixel, seconds, seconds > 0.0 ? samples / seconds : 0.0});
    }
    if (settings.time_limit_seconds > 0.0 && seconds >= settings.time_limit_seconds &&
        result.passes_done < settings.samples_per_pixel) {
      result.stop_reason = StopReason::time_limit;
      break;
    }
  }
  result.elapsed_seconds = elapsed();
  result.invalid_samples = invalid.load();
  return result;
}

}  // namespace prism
