#include "prism/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/core/sample_stream.h"
#include "prism/render/memory_estimate.h"
#include "prism/render/prepared_scene.h"
#include "prism/scene/camera_rays.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"

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

void hash_spectrum(Fnv1a& h, const color::PiecewiseLinearSpectrum& s) {
  h.value(s.wavelengths_nm().size());
  h.bytes(s.wavelengths_nm().data(), s.wavelengths_nm().size_bytes());
  h.bytes(s.values().data(), s.values().size_bytes());
}

// What changes a scene's pixels beyond the fields image_fingerprint hashed from the start,
// each only where it differs from its default, so that scenes without it keep the
// fingerprints of earlier versions (and their checkpoints still resume): shading
// attributes of meshes, instances, textures (texels and addressing), the material fields
// the first version left out, and light shapes. A checkpoint of a scene that differs in any
// of them no longer resumes as the other.
void hash_scene_details(Fnv1a& h, const Scene& scene) {
  const auto vector_if_any = [&h](const auto& v) {
    if (v.empty()) return;
    h.value(v.size());
    h.bytes(v.data(), v.size() * sizeof(v[0]));
  };
  for (const TriangleMesh& mesh : scene.meshes) {
    vector_if_any(mesh.normals);
    vector_if_any(mesh.uvs);
    vector_if_any(mesh.tangents);
    vector_if_any(mesh.tangent_signs);
  }
  for (const Instance& instance : scene.instances) {
    h.value(instance.mesh);
    h.value(instance.object_to_world.m);
    h.value(instance.object_to_world.translation);
  }
  for (const TextureImage& t : scene.textures) {
    h.value(t.width);
    h.value(t.height);
    h.value(t.channels);
    vector_if_any(t.texels);
    vector_if_any(t.codes);
    vector_if_any(t.rgbe);
    vector_if_any(t.halves);
    h.value(t.encoding);
    for (float v : {t.offset_u, t.offset_v, t.scale_u, t.scale_v, t.rotation_radians}) h.value(v);
    h.value(t.wrap_u);
    h.value(t.wrap_v);
  }
  const Material plain;
  for (const Material& m : scene.materials) {
    if (m.base_color_texture != plain.base_color_texture) h.value(m.base_color_texture);
    if (m.metallic_roughness_texture != plain.metallic_roughness_texture) h.value(m.metallic_roughness_texture);
    if (m.emission.texture != plain.emission.texture) h.value(m.emission.texture);
    if (m.emission.two_sided != plain.emission.two_sided) h.value(m.emission.two_sided);
    if (m.anisotropy != plain.anisotropy) h.value(m.anisotropy);
    if (m.anisotropy_rotation_rad != plain.anisotropy_rotation_rad) h.value(m.anisotropy_rotation_rad);
    if (m.anisotropy_texture != plain.anisotropy_texture) h.value(m.anisotropy_texture);
    if (m.microfacet != plain.microfacet) h.value(m.microfacet);
    if (m.conductor_fresnel != plain.conductor_fresnel) {
      h.value(m.conductor_fresnel);
      h.bytes(m.conductor_name.data(), m.conductor_name.size());
    }
    if (m.dispersion != plain.dispersion) {
      h.value(m.dispersion);
      h.value(m.dispersion_coefficients);
    }
    if (m.thin_walled != plain.thin_walled) h.value(m.thin_walled);
    if (m.transmission != plain.transmission) h.value(m.transmission);
    if (m.alpha_mode != plain.alpha_mode) {
      h.value(m.alpha_mode);
      h.value(m.alpha_cutoff);
    }
    if (m.opacity != plain.opacity) h.value(m.opacity);
    if (m.absorbs_inside()) {
      h.value(m.attenuation_color);
      h.value(m.attenuation_distance);
    }
    if (m.specular != plain.specular) h.value(m.specular);
    if (m.specular_color != plain.specular_color) h.value(m.specular_color);
    if (m.specular_texture != plain.specular_texture) h.value(m.specular_texture);
    if (m.specular_color_texture != plain.specular_color_texture) h.value(m.specular_color_texture);
    if (m.has_clearcoat()) {
      h.value(m.clearcoat);
      h.value(m.clearcoat_roughness);
      h.value(m.clearcoat_texture);
      h.value(m.clearcoat_roughness_texture);
      // Only where there is one, so coats without keep their earlier fingerprints.
      if (m.clearcoat_normal_texture != plain.clearcoat_normal_texture) {
        h.value(m.clearcoat_normal_texture);
        h.value(m.clearcoat_normal_scale);
      }
    }
    if (m.has_iridescence()) {
      h.value(m.iridescence);
      h.value(m.iridescence_ior);
      h.value(m.iridescence_thickness_min_nm);
      h.value(m.iridescence_thickness_max_nm);
      h.value(m.iridescence_texture);
      h.value(m.iridescence_thickness_texture);
    }
    if (m.has_sheen()) {
      h.value(m.sheen_color);
      h.value(m.sheen_roughness);
      h.value(m.sheen_color_texture);
      h.value(m.sheen_roughness_texture);
    }
  }
  const Light point;
  for (const Light& l : scene.lights) {
    if (l.color_space != point.color_space) h.value(l.color_space);
    if (l.type == LightType::spot) {
      h.value(l.spot_inner_angle_degrees);
      h.value(l.spot_outer_angle_degrees);
    }
    if (l.angular_diameter_degrees != point.angular_diameter_degrees) h.value(l.angular_diameter_degrees);
    if (l.type == LightType::environment) {
      if (l.environment_texture != point.environment_texture) h.value(l.environment_texture);
      if (l.environment_mapping != point.environment_mapping) h.value(l.environment_mapping);
      if (!(l.environment_to_world == Transform{})) {
        h.value(l.environment_to_world.m);
        h.value(l.environment_to_world.translation);
      }
    }
  }
}

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
  // 0 is pbrt-v4's maxdepth 0: emitted light seen directly, nothing scattered.
  if (s.path.max_depth < 0) throw UsageError(fmt::format("--max-depth must be at least 0 (got {})", s.path.max_depth));
  if (s.threads < 0) throw UsageError(fmt::format("--threads must be at least 1 (got {})", s.threads));
  if (!(s.time_limit_seconds >= 0.0)) throw UsageError("--time-limit must be a non-negative number of seconds");
  if (s.bounces_per_pass < 0)
    throw UsageError(fmt::format("--bounces-per-pass must be 0 (until paths end) or more (got {})", s.bounces_per_pass));
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
    // Spectra given as data, only where there are some (so other scenes keep their fingerprints).
    for (const auto* spectrum : {&m.base_color_spectrum, &m.emission.spectrum})
      if (*spectrum) hash_spectrum(h, **spectrum);
    // Only for wide-gamut base colours, so other scenes keep their fingerprints.
    if (m.base_color_space != ColorPickerSpace::srgb) h.value(m.base_color_space);
    // Only with a normal or bump map, so other scenes keep their fingerprints; checkpoints
    // of such scenes from before these maps were applied no longer match.
    if (m.normal_texture >= 0) {
      h.value(m.normal_texture);
      h.value(m.normal_scale);
    }
    if (m.bump_texture >= 0) {
      h.value(m.bump_texture);
      h.value(m.bump_scale);
    }
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
  h.value(settings.path.sampler);
  // Only when not the default, so default renders keep the fingerprints of earlier versions
  // (every light-sampling option is unbiased, so resuming across them still converges).
  const LightSamplerOptions default_light;
  if (settings.path.light.triangle != default_light.triangle ||
      settings.path.light.reuse_selection_sample != default_light.reuse_selection_sample) {
    h.value(settings.path.light.triangle);
    h.value(settings.path.light.reuse_selection_sample);
  }
  if (settings.path.normal_mapping != NormalMapping::classic) h.value(settings.path.normal_mapping);  // as above
  h.value(settings.transport.kind);
  h.value(settings.transport.wavelengths);
  h.value(settings.transport.wavelength_strategy);
  h.value(settings.transport.stratify_first_wavelengths);
  h.value(settings.transport.upsampling);
  h.bytes(settings.transport.working_space.data(), settings.transport.working_space.size());
  // Reflectances became E-relative (jakob_hanika_target_xyz_matrix,
  // mallett_yuksel_weights_under_e; in RGB transport measured reflectances likewise): every
  // coloured spectral pixel changed, so checkpoints from before must not resume into it.
  constexpr std::uint32_t kReflectanceConvention = 2;
  if (settings.transport.kind == TransportKind::spectral ||
      std::any_of(scene.materials.begin(), scene.materials.end(),
                  [](const Material& m) { return m.base_color_spectrum.has_value(); }))
    h.value(kReflectanceConvention);
  for (const auto& l : scene.lights) {
    h.value(l.type);
    h.value(l.position);
    h.value(l.direction);
    h.value(l.color);
    h.value(l.intensity);
    if (l.spectrum) hash_spectrum(h, *l.spectrum);
  }
  hash_scene_details(h, scene);
  // Only when requested, so renders without AOVs keep the fingerprints of earlier versions.
  if (settings.aovs.any()) h.value(settings.aovs.bits());
  return h.digest();
}

namespace {

template <class Mode>
void render_passes(const PreparedScene& prepared, const RenderSettings& settings,
                   const RenderHooks& hooks, RenderResult& result, int start_sample) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const Scene& scene = prepared.scene();
  const std::shared_ptr<const LightSampler> light_sampler = prepared.light_sampler(settings.path.light);
  const LightSampler& lights = *light_sampler;
  const PinholeCamera camera(scene.camera, settings.width, settings.height);
  const ColorContext<Mode> colors(scene, settings.transport);
  WavefrontIntegrator<Mode> integrator(scene, prepared.accel(), prepared.mip_pyramids(), lights, camera, colors,
                                       settings.path, settings.width, settings.height, settings.seed,
                                       settings.regenerate_paths);
  const auto cancelled = [&hooks] { return hooks.cancel && hooks.cancel->load(std::memory_order_relaxed); };

  int next_sample = start_sample;
  double last_checkpoint = 0.0;
  int pass_size = settings.samples_per_pass > 0 ? settings.samples_per_pass : 1;
  constexpr double kTargetPassSeconds = 0.5;
  while (next_sample < settings.samples_per_pixel) {
    if (cancelled()) {
      result.stop_reason = StopReason::cancelled;
      break;
    }
    const int count = std::min(pass_size, settings.samples_per_pixel - next_sample);
    const double pass_start = elapsed();
    const std::function<void()> after_bounces = [&] { hooks.on_bounces(result.film, next_sample); };
    const PassStatistics stats = integrator.render_samples(
        result.film, static_cast<std::uint32_t>(next_sample), static_cast<std::uint32_t>(count),
        settings.bounces_per_pass, hooks.on_bounces ? &after_bounces : nullptr);
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
      const double samples = static_cast<double>(next_sample - start_sample) * result.film.pixel_count();
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
  if (resume) {
    if (resume->film.width() != settings.width || resume->film.height() != settings.height)
      throw UsageError(fmt::format("checkpoint film is {}x{} but the render is {}x{}", resume->film.width(),
                                   resume->film.height(), settings.width, settings.height));
    if (resume->next_sample < settings.first_sample || resume->next_sample > settings.samples_per_pixel)
      throw UsageError(fmt::format("checkpoint ends at sample {}, outside the requested range {}:{}",
                                   resume->next_sample, settings.first_sample, settings.samples_per_pixel));
    if (resume->film.aovs() != settings.aovs)
      throw UsageError(fmt::format("checkpoint film keeps the AOVs '{}' but the render asks for '{}'",
                                   format_aov_list(resume->film.aovs()), format_aov_list(settings.aovs)));
    result.film = resume->film;
    next_sample = resume->next_sample;
  } else {
    result.film = Film(settings.width, settings.height, settings.aovs);
  }

  const TransportSettings& t = settings.transport;
  if (t.kind == TransportKind::rgb) {
    render_passes<RgbMode>(prepared, settings, hooks, result, next_sample);
  } else if (t.wavelengths == 3) {
    render_passes<SpectralMode<3>>(prepared, settings, hooks, result, next_sample);
  } else if (t.wavelengths == 8) {
    render_passes<SpectralMode<8>>(prepared, settings, hooks, result, next_sample);
  } else {
    render_passes<SpectralMode<4>>(prepared, settings, hooks, result, next_sample);
  }
  result.passes_done = result.next_sample - settings.first_sample;
  if (hooks.on_checkpoint) hooks.on_checkpoint(result.film, result.next_sample);
  result.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace prism
