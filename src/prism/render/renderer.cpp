#include "prism/render/renderer.h"

#include <chrono>
#include <cstring>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/core/sample_stream.h"
#include "prism/scene/camera_rays.h"
#include "prism/scene/emission.h"

namespace prism {
namespace {

// FNV-1a (Fowler, Noll, Vo) over raw bytes: stable across runs and platforms of the same
// endianness, which is all a fingerprint needs.
class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  std::uint64_t digest() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace

void validate_render_settings(const RenderSettings& s) {
  // 32768² matches the image-size limit the loaders use; beyond it the film alone needs
  // tens of gigabytes.
  constexpr int kMaxResolution = 32768;
  if (s.width < 1 || s.height < 1 || s.width > kMaxResolution || s.height > kMaxResolution)
    throw UsageError(fmt::format("resolution {}x{} is out of range (1 to {} per axis)", s.width, s.height, kMaxResolution));
  if (s.samples_per_pixel < 1) throw UsageError(fmt::format("--spp must be at least 1 (got {})", s.samples_per_pixel));
  if (s.first_sample < 0 || s.first_sample >= s.samples_per_pixel)
    throw UsageError(fmt::format("sample range {}:{} is empty or negative", s.first_sample, s.samples_per_pixel));
  if (s.path.max_depth < 1) throw UsageError(fmt::format("--max-depth must be at least 1 (got {})", s.path.max_depth));
  if (s.threads < 0) throw UsageError(fmt::format("--threads must be at least 1 (got {})", s.threads));
  if (!(s.time_limit_seconds >= 0.0)) throw UsageError("--time-limit must be a non-negative number of seconds");
}

std::uint64_t image_fingerprint(const Scene& scene, const RenderSettings& settings) {
  Fnv1a h;
  for (const auto& mesh : scene.meshes) {
    h.value(mesh.material);
    h.value(mesh.positions.size());
    h.bytes(mesh.positions.data(), mesh.positions.size() * sizeof(Vec3f));
    h.value(mesh.indices.size());
    h.bytes(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  }
  for (const auto& m : scene.materials) {
    h.value(m.type);
    h.value(m.base_color);
    h.value(m.roughness);
    h.value(m.metallic);
    h.value(m.ior);
    h.value(m.emission.color);
    h.value(m.emission.color_space);
    h.value(m.emission.luminance_nits);
  }
  const Camera& c = scene.camera;
  for (float v : {c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z,
                  c.fov_degrees, c.aperture_radius, c.focus_distance})
    h.value(v);
  h.value(settings.width);
  h.value(settings.height);
  h.value(settings.seed);
  h.value(settings.path.max_depth);
  h.value(settings.path.russian_roulette_depth);
  h.value(settings.path.estimator);
  return h.digest();
}

RenderResult render(const Scene& scene, const RenderSettings& settings, const RenderHooks& hooks,
                    const ResumeState* resume) {
  validate_render_settings(settings);
  validate_scene(scene);
  const ThreadLimit thread_limit(settings.threads);
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  RenderResult result;
  int next_sample = settings.first_sample;
  if (resume) {
    if (resume->film.width() != settings.width || resume->film.height() != settings.height)
      throw UsageError(fmt::format("checkpoint film is {}x{} but the render is {}x{}", resume->film.width(),
                                   resume->film.height(), settings.width, settings.height));
    if (resume->next_sample < settings.first_sample || resume->next_sample > settings.samples_per_pixel)
      throw UsageError(fmt::format("checkpoint ends at sample {}, outside the requested range {}:{}",
                                   resume->next_sample, settings.first_sample, settings.samples_per_pixel));
    result.film = resume->film;
    next_sample = resume->next_sample;
  } else {
    result.film = Film(settings.width, settings.height);
  }

  const EmbreeAccel accel(scene);
  const LightSampler lights(scene);
  PathContext context{scene, accel, lights, settings.path, {}};
  for (const Material& m : scene.materials)
    context.emitted_radiance.emplace_back(emission_radiance_rgb(m.emission, color::color_space("srgb")));
  const PinholeCamera camera(scene.camera, settings.width, settings.height);
  std::atomic<std::uint64_t> invalid{0};
  const auto cancelled = [&hooks] { return hooks.cancel && hooks.cancel->load(std::memory_order_relaxed); };
  double last_checkpoint = 0.0;

  while (next_sample < settings.samples_per_pixel) {
    if (cancelled()) {
      result.stop_reason = StopReason::cancelled;
      break;
    }
    const auto sample_index = static_cast<std::uint64_t>(next_sample);
    parallel_for(static_cast<std::size_t>(settings.height), 1, [&](std::size_t row_begin, std::size_t row_end) {
      std::uint64_t local_invalid = 0;
      for (std::size_t y = row_begin; y < row_end; ++y) {
        for (int x = 0; x < settings.width; ++x) {
          const std::size_t pixel = y * static_cast<std::size_t>(settings.width) + static_cast<std::size_t>(x);
          Pcg32 rng = make_sample_stream(settings.seed, pixel, sample_index);
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
    ++next_sample;
    const double seconds = elapsed();
    const int passes_this_run = next_sample - (resume ? resume->next_sample : settings.first_sample);
    if (hooks.on_pass) {
      const double samples = static_cast<double>(passes_this_run) * result.film.pixel_count();
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
  result.passes_done = next_sample - settings.first_sample;
  if (hooks.on_checkpoint) hooks.on_checkpoint(result.film, next_sample);
  result.elapsed_seconds = elapsed();
  result.invalid_samples = invalid.load();
  return result;
}

}  // namespace prism
