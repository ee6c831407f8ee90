#include "prism/render/renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <optional>

#include <fmt/format.h>

#include "prism/core/enum_names.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/core/sample_stream.h"
#include "prism/render/memory_estimate.h"
#include "prism/render/prepared_scene.h"
#include "prism/render/reference_path_tracer.h"
#include "prism/scene/camera_rays.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"

namespace prism {

void validate_render_settings(const RenderSettings& s) {
  // 32768² matches the image-size limit the loaders use; beyond it the film alone needs
  // tens of gigabytes.
  constexpr int kMaxResolution = 32768;
  if (s.width < 1 || s.height < 1 || s.width > kMaxResolution || s.height > kMaxResolution)
    throw UsageError(fmt::format("resolution {}x{} is out of range (1 to {} per axis)", s.width, s.height, kMaxResolution));
  if (s.samples_per_pixel < 1) throw UsageError(fmt::format("--spp must be at least 1 (got {})", s.samples_per_pixel));
  if (s.first_sample < 0 || s.first_sample >= s.samples_per_pixel)
    throw UsageError(fmt::format("sample range {}:{} is empty or negative", s.first_sample, s.samples_per_pixel));
  // 0 is pbrt-v4's maxdepth 0: emitted light seen directly, nothing scattered.
  if (s.path.max_depth < 0) throw UsageError(fmt::format("--max-depth must be at least 0 (got {})", s.path.max_depth));
  if (s.threads < 0) throw UsageError(fmt::format("--threads must be at least 1 (got {})", s.threads));
  if (!(s.time_limit_seconds >= 0.0)) throw UsageError("--time-limit must be a non-negative number of seconds");
  if (s.bounces_per_pass < 0)
    throw UsageError(fmt::format("--bounces-per-pass must be 0 (until paths end) or more (got {})", s.bounces_per_pass));
  validate_adaptive_sampling(s.adaptive);
  if (s.adaptive.enabled() && s.first_sample > 0)
    throw UsageError("--noise-threshold cannot be combined with --sample-range (see docs/farm-rendering.md)");
}


constexpr std::array<EnumName<IntegratorKind>, 2> kIntegratorNames{{
    {IntegratorKind::wavefront, "wavefront"},
    {IntegratorKind::reference, "reference"},
}};

std::string_view integrator_name(IntegratorKind kind) { return enum_name(kIntegratorNames, kind); }

IntegratorKind parse_integrator(std::string_view name) {
  if (const std::optional<IntegratorKind> kind = enum_value(kIntegratorNames, name)) return *kind;
  throw UsageError(fmt::format("unknown --integrator '{}' ({})", name, enum_name_list(kIntegratorNames)));
}

std::vector<std::string> integrator_names() { return enum_names(kIntegratorNames); }

namespace {

template <class Integrator>
void render_passes(Integrator& integrator, const RenderSettings& settings, const RenderHooks& hooks,
                   RenderResult& result, int start_sample) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const auto cancelled = [&hooks] { return hooks.cancel && hooks.cancel->load(std::memory_order_relaxed); };

  int next_sample = start_sample;
  double last_checkpoint = 0.0;
  int pass_size = settings.samples_per_pass > 0 ? settings.samples_per_pass : 1;
  constexpr double kTargetPassSeconds = 0.5;
  std::uint64_t samples_taken = 0;
  while (next_sample < settings.samples_per_pixel) {
    if (cancelled()) {
      result.stop_reason = StopReason::cancelled;
      break;
    }
    const double pass_start = elapsed();  // the mask below is part of the pass's time
    // Adaptive sampling: the pixels that render this pass, from the film alone, and a pass
    // that ends at the next decision boundary at the latest (adaptive_sampling.h).
    const std::optional<std::vector<std::uint8_t>> active =
        adaptive_active_pixels(result.film, result.film_space, settings.adaptive, next_sample);
    const std::size_t active_pixels =
        active ? static_cast<std::size_t>(std::count(active->begin(), active->end(), std::uint8_t{1}))
               : result.film.pixel_count();
    if (active_pixels == 0) {
      next_sample = settings.samples_per_pixel;  // every pixel has stopped, for good
      break;
    }
    const int boundary = next_adaptive_boundary(settings.adaptive, next_sample, settings.samples_per_pixel);
    const int count = std::min(pass_size, boundary - next_sample);
    const std::function<void()> after_bounces = [&] { hooks.on_bounces(result.film, next_sample); };
    const PassStatistics stats = integrator.render_samples(
        result.film, static_cast<std::uint32_t>(next_sample), static_cast<std::uint32_t>(count),
        settings.bounces_per_pass, hooks.on_bounces ? &after_bounces : nullptr, active ? active->data() : nullptr);
    samples_taken += static_cast<std::uint64_t>(count) * active_pixels;
    const double seconds = elapsed();
    result.pass_seconds.push_back(seconds - pass_start);
    result.pass_samples.push_back(count);
    result.pass_live_paths.push_back(stats.live_paths_per_step);
    result.rays += stats.rays;
    result.shadow_rays += stats.shadow_rays;
    result.lane_shaded_hits += stats.lane_shaded_hits;
    result.camera_packet_rays += stats.camera_packet_rays;
    result.invalid_samples += stats.invalid_samples;
    next_sample += count;
    if (settings.samples_per_pass == 0) {
      // Grouping samples into passes does not change the image (see wavefront_integrator.h),
      // so the pass size may follow the measured speed.
      const double per_sample = (seconds - pass_start) / count;
      pass_size = std::clamp(static_cast<int>(kTargetPassSeconds / std::max(per_sample, 1e-6)), 1, 64);
    }
    if (hooks.on_pass) {
      const auto samples = static_cast<double>(samples_taken);
      hooks.on_pass({next_sample - settings.first_sample, settings.samples_per_pixel - settings.first_sample, seconds,
                     seconds > 0.0 ? samples / seconds : 0.0});
    }
    if (hooks.on_checkpoint && hooks.checkpoint_interval_seconds > 0.0 &&
        seconds - last_checkpoint >= hooks.checkpoint_interval_seconds && next_sample < settings.samples_per_pixel) {
      hooks.on_checkpoint(result.film, next_sample);
      last_checkpoint = seconds;
    }
    if (settings.time_limit_seconds > 0.0 && seconds >= settings.time_limit_seconds &&
        next_sample < settings.samples_per_pixel) {
      result.stop_reason = StopReason::time_limit;
      break;
    }
  }
  result.next_sample = next_sample;
}

// The integrator `settings` asks for, in transport mode Mode, over the prepared scene.
template <class Mode>
void render_in_mode(const PreparedScene& prepared, const RenderSettings& settings, const RenderHooks& hooks,
                    RenderResult& result, int start_sample) {
  const Scene& scene = prepared.scene();
  const std::shared_ptr<const LightSampler> lights = prepared.light_sampler(settings.path.light);
  const PinholeCamera camera(scene.camera, settings.width, settings.height);
  const ColorContext<Mode> colors(scene, settings.transport);
  if (settings.integrator == IntegratorKind::reference) {
    ReferencePathTracer<Mode> integrator(scene, prepared.accel(), prepared.mip_pyramids(), *lights, camera, colors,
                                         settings.path, settings.width, settings.height, settings.seed);
    render_passes(integrator, settings, hooks, result, start_sample);
  } else {
    WavefrontIntegrator<Mode> integrator(scene, prepared.accel(), prepared.mip_pyramids(), *lights, camera, colors,
                                         settings.path, settings.width, settings.height, settings.seed,
                                         settings.regenerate_paths);
    render_passes(integrator, settings, hooks, result, start_sample);
  }
}

}  // namespace

RenderResult render(const Scene& input_scene, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume) {
  validate_render_settings(settings);
  validate_transport(settings.transport);
  validate_scene(input_scene);
  // Reliability (--memory-limit): refuse a render that cannot fit before allocating it.
  check_render_memory(input_scene, settings, settings.memory_limit_bytes);
  // --threads holds for the preparation too (BVH build, mip pyramids, light sampler).
  const ThreadLimit thread_limit(settings.threads);
  const PreparedScene prepared(input_scene);
  return render(prepared, settings, hooks, resume);
}

RenderResult render(Scene&& input_scene, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume) {
  validate_render_settings(settings);
  validate_transport(settings.transport);
  validate_scene(input_scene);
  check_render_memory(input_scene, settings, settings.memory_limit_bytes, SceneHandover::moved);
  const ThreadLimit thread_limit(settings.threads);  // as above
  const PreparedScene prepared(std::move(input_scene));
  return render(prepared, settings, hooks, resume);
}

RenderResult render(const PreparedScene& prepared, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume) {
  validate_render_settings(settings);
  validate_transport(settings.transport);
  // The memory check belongs before preparing (render(const Scene&) above, or the caller):
  // by now the geometry and its BVH are allocated.
  const ThreadLimit thread_limit(settings.threads);
  const auto start = std::chrono::steady_clock::now();

  RenderResult result;
  result.film_space = film_color_space(settings.transport);
  int next_sample = settings.first_sample;
  const AovSet film_aovs = adaptive_film_aovs(settings.aovs, settings.adaptive);
  if (resume) {
    if (resume->film.width() != settings.width || resume->film.height() != settings.height)
      throw UsageError(fmt::format("checkpoint film is {}x{} but the render is {}x{}", resume->film.width(),
                                   resume->film.height(), settings.width, settings.height));
    if (resume->next_sample < settings.first_sample || resume->next_sample > settings.samples_per_pixel)
      throw UsageError(fmt::format("checkpoint ends at sample {}, outside the requested range {}:{}",
                                   resume->next_sample, settings.first_sample, settings.samples_per_pixel));
    if (resume->film.aovs() != film_aovs)
      throw UsageError(fmt::format("checkpoint film keeps the AOVs '{}' but the render asks for '{}'",
                                   format_aov_list(resume->film.aovs()), format_aov_list(film_aovs)));
    result.film = resume->film;
    next_sample = resume->next_sample;
  } else {
    result.film = Film(settings.width, settings.height, film_aovs);
  }

  const TransportSettings& t = settings.transport;
  if (t.kind == TransportKind::rgb) {
    render_in_mode<RgbMode>(prepared, settings, hooks, result, next_sample);
  } else if (t.wavelengths == 3) {
    render_in_mode<SpectralMode<3>>(prepared, settings, hooks, result, next_sample);
  } else if (t.wavelengths == 8) {
    render_in_mode<SpectralMode<8>>(prepared, settings, hooks, result, next_sample);
  } else {
    render_in_mode<SpectralMode<4>>(prepared, settings, hooks, result, next_sample);
  }
  result.passes_done = result.next_sample - settings.first_sample;
  if (hooks.on_checkpoint) hooks.on_checkpoint(result.film, result.next_sample);
  result.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace prism
