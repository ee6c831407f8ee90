// `prism render`: render a scene progressively and write EXR and/or PNG images.
#include <atomic>
#include <csignal>
#include <filesystem>
#include <utility>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "aov_exr.h"
#include "command.h"
#include "display_options.h"
#include "environment_options.h"
#include "progress_reporter.h"
#include "render_denoise.h"
#include "render_outputs.h"
#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/core/printable_text.h"
#include "prism/core/process_memory.h"
#include "prism/core/version.h"
#include "prism/display/exposure_metering.h"
#include "prism/io/atomic_file.h"
#include "prism/io/exr.h"
#include "prism/io/radiance_hdr_writer.h"
#include "prism/io/png.h"
#include "prism/render/aov_images.h"
#include "prism/render/checkpoint.h"
#include "prism/render/first_picture.h"
#include "prism/render/memory_estimate.h"
#include "prism/render/renderer.h"
#include "prism/render/simd_level.h"
#include "prism/scene/camera_json.h"
#include "prism/scene/camera_selection.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/load_scene.h"

namespace prism::cli {
namespace {

struct RenderOptions {
  std::string scene = "cornell-box";
  bool allow_external_paths = false;  // scene files may refer to files outside their folder
  std::vector<std::string> outputs;
  int spp = 64;
  int max_depth = PathSettings{}.max_depth;  // the scene file's, when it names one (first_picture.h)
  std::uint64_t seed = 0;
  int threads = 0;
  bool threads_given = false;
  double time_limit_seconds = 0.0;
  int width = 0, height = 0;  // 0: the scene's default
  std::string estimator = "mis";
  std::string normal_mapping;  // empty: the scene's choice, else classic
  std::string sampler = std::string(sampler_name(PathSettings{}.sampler));
  std::string simd = "auto";
  std::string integrator = "wavefront";
  std::string mode = "spectral";
  int wavelengths = 4;
  std::string wavelength_sampling = "cosh";
  std::string upsampling = "jakob-hanika";
  std::string working_space = "srgb";
  bool wavelength_stratification = false;
  int samples_per_pass = 0;
  bool max_depth_given = false;
  std::string exr_space = "working";
  std::string camera;  // --camera NAME|INDEX
  std::string material_variant;  // --variant NAME (glTF KHR_materials_variants)
  std::string camera_json;
  EnvironmentOverride environment;  // --environment FILE|uniform
  DisplayCliOptions display;
  std::string sample_range;  // "START:END"
  std::string checkpoint;
  double checkpoint_every_seconds = 60.0;
  std::string resume;
  bool spp_given = false;
  std::string memory_limit;  // BYTES or SIZE with K/M/G/T; empty: 90 % of physical memory
  std::string aovs;          // "albedo,normal,depth,variance" subset; empty: none
  bool denoise = false;      // --denoise: outputs show the denoised beauty (render_denoise.h)
  AdaptiveSamplingSettings adaptive;  // --noise-threshold, --adaptive-min-samples
};

// Parses "START:END" (END exclusive) into first_sample / samples_per_pixel.
void apply_sample_range(const std::string& text, RenderSettings& settings) {
  const auto colon = text.find(':');
  std::size_t used_a = 0, used_b = 0;
  try {
    if (colon == std::string::npos) throw std::invalid_argument("no colon");
    const int begin = std::stoi(text.substr(0, colon), &used_a);
    const int end = std::stoi(text.substr(colon + 1), &used_b);
    if (used_a != colon || used_b != text.size() - colon - 1) throw std::invalid_argument("trailing text");
    settings.first_sample = begin;
    settings.samples_per_pixel = end;
  } catch (const std::logic_error&) {
    throw UsageError(fmt::format("--sample-range '{}' is not START:END (sample indices, END exclusive)", text));
  }
  if (settings.first_sample < 0 || settings.samples_per_pixel <= settings.first_sample)
    throw UsageError(fmt::format("--sample-range '{}' is empty or negative", text));
}

enum class OutputFormat { exr, radiance_hdr, display };

OutputFormat output_format(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".exr" || ext == ".EXR") return OutputFormat::exr;
  if (ext == ".hdr" || ext == ".HDR") return OutputFormat::radiance_hdr;
  if (ext == ".png" || ext == ".PNG" || ext == ".avif" || ext == ".AVIF") return OutputFormat::display;
  throw UsageError(
      fmt::format("unknown output extension '{}' in '{}' (supported: .exr, .hdr, .png, .avif)", ext, path.string()));
}

LightEstimator parse_estimator(const std::string& name) {
  if (const auto estimator = parse_light_estimator(name)) return *estimator;
  throw UsageError(fmt::format("unknown --estimator '{}' ({})", name, kLightEstimatorNames));
}

SamplerKind parse_sampler_option(const std::string& name) {
  if (const auto kind = parse_sampler(name)) return *kind;
  throw UsageError(fmt::format("unknown --sampler '{}' (independent, sobol, zsobol)", name));
}

// SIGINT/SIGTERM ask the render to stop after the current row; a second signal uses the
// default action (immediate exit). Outputs are written atomically, so an immediate exit
// never leaves a truncated image.
std::atomic<bool> g_cancel{false};
std::atomic<int> g_signal{0};

extern "C" void on_interrupt(int signal) {
  g_signal.store(signal);
  g_cancel.store(true);
  std::signal(signal, SIG_DFL);
}

std::string hex(std::uint64_t v) { return fmt::format("{:016x}", v); }

ExrChromaticities chromaticities_of(const color::ColorSpace& space) {
  auto f = [](double v) { return static_cast<float>(v); };
  return {f(space.red.x), f(space.red.y), f(space.green.x), f(space.green.y),
          f(space.blue.x), f(space.blue.y), f(space.white.x), f(space.white.y)};
}

// The film's means converted to `space` (one 3×3, with Bradford adaptation between whites).
ImageRgbF film_image(const Film& film, const color::ColorSpace& film_space, const color::ColorSpace& space) {
  const Mat3 m = color::conversion_matrix(film_space, space);
  ImageRgbF image{film.width(), film.height(), std::vector<float>(3 * film.pixel_count())};
  for (std::size_t i = 0; i < film.pixel_count(); ++i) {
    const Vec3d v = m * film.mean(i);
    for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = static_cast<float>(v[c]);
  }
  return image;
}

void write_outputs(const std::vector<std::filesystem::path>& outputs, const RenderResult& result,
                   const std::string& scene_name, const RenderSettings& settings, std::uint64_t fingerprint,
                   const RenderOptions& o, const DisplayCliOptions& display, std::optional<double> ev100) {
  const color::ColorSpace& working = color::color_space(settings.transport.working_space);
  const std::optional<ImageRgbF> denoised =
      o.denoise ? std::optional(denoise_film(result.film, result.film_space, working)) : std::nullopt;
  for (const auto& path : outputs) {
    if (output_format(path) == OutputFormat::exr) {
      ExrMetadata meta;
      meta.strings["prism:version"] = kVersion;
      meta.strings["prism:scene"] = scene_name;
      meta.strings["prism:transport"] = describe(settings.transport);
      meta.strings["prism:sampler"] = std::string(sampler_name(settings.path.sampler));
      meta.strings["prism:integrator"] = std::string(integrator_name(settings.integrator));
      meta.strings["prism:estimator"] = std::string(light_estimator_name(settings.path.estimator));
      meta.strings["prism:normalMapping"] = std::string(normal_mapping_name(settings.path.normal_mapping));
      meta.ints["prism:spp"] = result.passes_done;
      meta.doubles["prism:renderSeconds"] = result.elapsed_seconds;
      // What `prism merge` needs to combine partial renders of one image.
      meta.ints["prism:sampleBegin"] = settings.first_sample;
      meta.ints["prism:sampleEnd"] = result.next_sample;
      meta.strings["prism:fingerprint"] = hex(fingerprint);
      if (settings.adaptive.enabled()) {
        meta.doubles["prism:noiseThreshold"] = settings.adaptive.noise_threshold;
        meta.ints["prism:adaptiveMinSamples"] = settings.adaptive.min_samples;
      }
      // The exposure the display outputs used (metered or given): `--ev100` repeats them.
      if (ev100) meta.doubles["prism:ev100"] = *ev100;
      // Pixel values are luminance-scaled: Y = 1 is one nit.
      const color::ColorSpace& space = o.exr_space == "film" ? result.film_space : working;
      if (settings.aovs.any()) meta.strings["prism:aovs"] = format_aov_list(settings.aovs);
      const AovImages aovs = film_aov_images(result.film, color::conversion_matrix(result.film_space, space));
      std::vector<ExrChannelGroup> layers = aov_exr_channels(aovs);
      ImageRgbF beauty = film_image(result.film, result.film_space, space);
      if (denoised) beauty = exr_denoised_beauty(beauty, *denoised, working, space, layers);
      write_exr(path, beauty, chromaticities_of(space), meta, {}, layers);
    } else if (output_format(path) == OutputFormat::radiance_hdr) {
      // Scene-referred like the EXR, in the same space: a spectral film in XYZ is written
      // as XYZE, unconverted.
      const color::ColorSpace& space = o.exr_space == "film" ? result.film_space : working;
      const RadianceWriteReport report =
          write_radiance_hdr(path,
                             denoised ? convert_image(*denoised, working, space)
                                      : film_image(result.film, result.film_space, space),
                             space, fmt::format("Prism {}", kVersion));
      if (report.clipped_pixels > 0)
        fmt::print(stderr,
                   "prism: warning: '{}': {} pixels lie outside {} (a negative channel) and were written with it at 0, "
                   "which RGBE cannot hold; an .exr output keeps them\n",
                   path.string(), report.clipped_pixels, space.name);
    } else {
      // Display-referred outputs go through the display pipeline (exposure, ACES, encoding);
      // they hold the beauty only, or the normal AOV for --view normal.
      std::optional<ImageRgbF> normals;
      if (result.film.aovs().normal) normals = film_aov_images(result.film, Mat3::identity()).normal;
      DisplayCliOptions with_text = display;
      if (settings.adaptive.enabled()) {
        with_text.extra_png_text.emplace_back("prism:noiseThreshold", fmt::format("{}", settings.adaptive.noise_threshold));
        with_text.extra_png_text.emplace_back("prism:adaptiveMinSamples", fmt::format("{}", settings.adaptive.min_samples));
      }
      write_display_output(path, denoised ? *denoised : film_image(result.film, result.film_space, working), working,
                           with_text, normals);
    }
  }
}

int run_render(const RenderOptions& o) {
  RenderSettings settings;
  settings.samples_per_pixel = o.spp;
  settings.path.max_depth = o.max_depth;
  settings.path.estimator = parse_estimator(o.estimator);
  if (!o.normal_mapping.empty()) {
    const std::optional<NormalMapping> model = parse_normal_mapping(o.normal_mapping);
    if (!model)
      throw UsageError(fmt::format("unknown --normal-mapping '{}' ({})", o.normal_mapping, kNormalMappingNames));
    settings.path.normal_mapping = *model;
  }
  settings.path.sampler = parse_sampler_option(o.sampler);
  settings.integrator = parse_integrator(o.integrator);
  settings.path.simd = parse_simd_level(o.simd);
  require_simd_level(settings.path.simd);
  if (o.mode != "spectral" && o.mode != "rgb") throw UsageError(fmt::format("unknown --mode '{}' (spectral, rgb)", o.mode));
  settings.transport.kind = o.mode == "rgb" ? TransportKind::rgb : TransportKind::spectral;
  settings.transport.wavelengths = o.wavelengths;
  settings.transport.wavelength_strategy = color::parse_wavelength_strategy(o.wavelength_sampling);
  settings.transport.stratify_first_wavelengths = o.wavelength_stratification;
  if (o.upsampling != "jakob-hanika" && o.upsampling != "mallett-yuksel")
    throw UsageError(fmt::format("unknown --upsampling '{}' (jakob-hanika, mallett-yuksel)", o.upsampling));
  settings.transport.upsampling = o.upsampling == "mallett-yuksel" ? Upsampling::mallett_yuksel : Upsampling::jakob_hanika;
  settings.transport.working_space = color::color_space(o.working_space).name;
  validate_transport(settings.transport);
  if (o.samples_per_pass < 0) throw UsageError("--samples-per-pass must be at least 1");
  settings.samples_per_pass = o.samples_per_pass;
  if (o.exr_space != "working" && o.exr_space != "film")
    throw UsageError(fmt::format("unknown --exr-space '{}' (working, film)", o.exr_space));
  settings.seed = o.seed;
  settings.threads = o.threads;
  settings.time_limit_seconds = o.time_limit_seconds;
  if (o.threads_given && o.threads < 1)
    throw UsageError(fmt::format("--threads must be at least 1 (got {}; omit it to use all cores)", o.threads));
  // The whole command keeps to --threads: loading (texture decoding), the BVH build and
  // the display outputs as well as the render.
  const ThreadLimit thread_limit(o.threads);
  if (o.width < 0 || o.height < 0) throw UsageError("--width and --height must be positive");
  if (!o.aovs.empty()) settings.aovs = parse_aov_list(o.aovs);
  if (o.denoise) add_denoise_aovs(settings.aovs);
  validate_adaptive_sampling(o.adaptive);
  // Parts of a farm split would each decide on their own samples (docs/farm-rendering.md).
  if (o.adaptive.enabled() && !o.sample_range.empty())
    throw UsageError("--noise-threshold cannot be combined with --sample-range (see docs/farm-rendering.md)");
  settings.adaptive = o.adaptive;
  // The rule reads the variance AOV's sums, so an adaptive render keeps (and writes) them.
  settings.aovs = adaptive_film_aovs(settings.aovs, settings.adaptive);
  // A part of a farm split must stay noisy: `prism merge` adds parts' beauties and variances.
  if (o.denoise && !o.sample_range.empty())
    throw UsageError("--denoise cannot be combined with --sample-range: run `prism denoise` on the merged EXR");
  // A display output's normal view shows the normal AOV: keep it when that view is asked for.
  if (display::DebugView::normal == selected_debug_view(o.display)) settings.aovs.normal = true;

  std::vector<std::filesystem::path> outputs;
  const std::vector<std::string> names =
      o.outputs.empty() ? std::vector<std::string>{"render.exr", "render.png"} : o.outputs;
  for (const auto& n : names) outputs.emplace_back(n);
  // Check everything that can be checked before spending time on the render.
  for (const auto& p : outputs) output_format(p);
  // --memory-limit already applies while loading: textures are checked from their headers.
  const std::uint64_t memory_limit = o.memory_limit.empty() ? 0 : parse_memory_size(o.memory_limit);
  MemoryBudget load_budget(memory_limit > 0 ? memory_limit : default_memory_limit());
  Scene scene = load_scene(o.scene, LoadOptions{.allow_external_paths = o.allow_external_paths,
                                                .memory_budget = &load_budget,
                                                .material_variant = o.material_variant});
  if (!o.camera.empty()) select_camera(scene, o.camera);
  if (!o.camera_json.empty()) scene.camera = read_camera_json(o.camera_json, scene.camera);
  apply_environment_override(scene, o.environment,
                             LoadOptions{.allow_external_paths = true, .memory_budget = &load_budget});
  for (const std::string& w : scene.warnings) fmt::print(stderr, "prism: warning: {}\n", printable_text(w));
  if (const auto warning = no_emitters_warning(scene)) fmt::print(stderr, "prism: warning: {}\n", *warning);
  for (std::size_t i = 1, n = 0; i <= scene.lights.size(); ++i)
    if (scene.lights[i - 1].type == LightType::environment && ++n == 2)
      fmt::print(stderr, "prism: warning: only the first environment light is used\n");
  // The first picture's defaults (first_picture.h): the scene camera's physical exposure
  // applies unless the command line sets one; without either the film is metered.
  const FirstPicture first = first_picture_defaults(scene);
  DisplayCliOptions display = o.display;
  const bool exposure_given = display.ev100 || display.f_number || display.shutter_s || display.iso;
  if (!exposure_given && !display.auto_exposure && first.camera_ev100) display.ev100 = first.camera_ev100;
  const bool metered = !display.ev100 && !display.f_number && !display.shutter_s && !display.iso;
  const RenderOutputs chosen = render_outputs(scene, o.outputs);  // the scene's own Film "filename", or -o
  outputs = chosen.paths;
  if (!chosen.note.empty()) fmt::print(stderr, "prism: note: {}\n", printable_text(chosen.note));
  for (const auto& p : outputs) {
    if (output_format(p) == OutputFormat::display)
      validate_display_output(p, display);  // bad display options fail before rendering
    else
      check_writable_output(p);
  }
  settings.width = o.width > 0 ? o.width : scene.default_width;
  settings.height = o.height > 0 ? o.height : scene.default_height;
  if (o.spp_given == false && o.sample_range.empty() && scene.default_spp > 0) settings.samples_per_pixel = scene.default_spp;
  if (!o.max_depth_given) settings.path.max_depth = first.path.max_depth;
  if (o.normal_mapping.empty() && scene.default_normal_mapping)
    settings.path.normal_mapping = *scene.default_normal_mapping;
  // --render-scale: render a fraction of the pixels; display outputs are upscaled back.
  if (!(o.display.render_scale > 0.0 && o.display.render_scale <= 1.0))
    throw UsageError("--render-scale must be in (0, 1]");
  if (o.display.render_scale < 1.0) {
    settings.width = std::max(1, static_cast<int>(std::lround(settings.width * o.display.render_scale)));
    settings.height = std::max(1, static_cast<int>(std::lround(settings.height * o.display.render_scale)));
  }
  if (!o.sample_range.empty()) {
    if (o.spp_given) throw UsageError("give either --spp or --sample-range, not both");
    apply_sample_range(o.sample_range, settings);
  }
  validate_render_settings(settings);
  settings.memory_limit_bytes = memory_limit;
  // Before any film is allocated. The render takes the loaded scene over (no second copy).
  check_render_memory(scene, settings, settings.memory_limit_bytes, SceneHandover::moved);
  const std::uint64_t fingerprint = image_fingerprint(scene, settings);

  // Resuming: the checkpoint must come from the same scene and settings. It keeps being
  // updated in place unless --checkpoint names another file.
  std::optional<ResumeState> resume;
  std::string checkpoint_path = o.checkpoint.empty() ? o.resume : o.checkpoint;
  if (!o.resume.empty()) {
    Checkpoint c = read_checkpoint(o.resume);
    if (c.fingerprint != fingerprint || c.first_sample != settings.first_sample)
      throw UsageError(fmt::format("checkpoint '{}' was made with a different scene or settings", o.resume));
    if (c.next_sample > settings.samples_per_pixel)
      throw UsageError(fmt::format("checkpoint '{}' already holds {} spp, more than --spp {}", o.resume,
                                   c.next_sample - c.first_sample, settings.samples_per_pixel));
    resume = ResumeState{std::move(c.film), c.next_sample};
  }
  if (!checkpoint_path.empty()) check_writable_output(checkpoint_path);
  if (!(o.checkpoint_every_seconds > 0.0)) throw UsageError("--checkpoint-every must be a positive number of seconds");

  g_cancel = false;
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  ProgressReporter progress(stderr);
  RenderHooks hooks;
  hooks.on_pass = [&](const RenderProgress& p) { progress.on_pass(p); };
  hooks.cancel = &g_cancel;
  if (!checkpoint_path.empty()) {
    hooks.checkpoint_interval_seconds = o.checkpoint_every_seconds;
    hooks.on_checkpoint = [&](const Film& film, int next_sample) {
      write_checkpoint(checkpoint_path, Checkpoint{fingerprint, settings.first_sample, next_sample, film});
    };
  }
  const std::string scene_name = scene.name;
  // Prepared here rather than inside render() so that the metering's coverage pass can
  // trace the same BVH afterwards.
  const PreparedScene prepared(std::move(scene));
  RenderResult result = render(prepared, settings, hooks, resume ? &*resume : nullptr);
  progress.finish();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);

  std::optional<double> ev100 = display.ev100;
  if (metered) {
    display::MeteringSettings metering = first.metering;
    metering.key = display.key;
    ev100 = meter_rendered_film(prepared, result.film, result.film_space, metering).ev100;
    display.ev100 = ev100;
    display.auto_exposure = false;
  } else if (!ev100) {
    ev100 = make_display_settings(display).exposure_ev100;  // --f-number/--shutter/--iso
  }
  write_outputs(outputs, result, scene_name, settings, fingerprint, o, display, ev100);

  const double samples = static_cast<double>(result.passes_done) * result.film.pixel_count();
  std::vector<std::string> written;
  for (const auto& p : outputs) written.push_back(p.string());
  if (!checkpoint_path.empty()) written.push_back(checkpoint_path + " (checkpoint)");
  // The process' own peak resident set (load, BVH, film, outputs): what the render needed.
  const auto peak_bytes = peak_resident_set_bytes();
  const std::string peak =
      peak_bytes ? fmt::format(", peak memory {} MiB", (*peak_bytes + (1u << 19)) >> 20) : std::string();
  const double samples_per_second = result.elapsed_seconds > 0 ? samples / result.elapsed_seconds : 0.0;
  const std::string exposure = ev100 ? fmt::format(", EV100 {}{}", *ev100, metered ? " metered" : "") : "";
  fmt::print("prism: rendered {} {}x{}, {} spp in {:.2f} s ({:.2f} M samples/s{}{}) -> {}\n", scene_name,
             settings.width, settings.height, result.passes_done, result.elapsed_seconds, samples_per_second * 1e-6,
             peak, exposure, fmt::join(written, ", "));
  if (result.invalid_samples > 0)
    fmt::print("prism: {} invalid samples (NaN/Inf) discarded\n", result.invalid_samples);
  if (result.stop_reason == StopReason::time_limit)
    fmt::print("prism: time limit reached after {} of {} spp\n", result.passes_done, settings.samples_per_pixel);
  if (result.stop_reason == StopReason::cancelled) {
    fmt::print("prism: interrupted; images hold the {} complete passes rendered so far{}\n", result.passes_done,
               checkpoint_path.empty() ? "" : "; continue with --resume " + checkpoint_path);
    std::fflush(stdout);
    return 128 + g_signal.load();
  }
  return 0;
}

}  // namespace

void add_render_command(CLI::App& root, Action& action) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = root.add_subcommand("render", "Render a scene to EXR or .hdr (linear, scene-referred) and/or PNG or AVIF (display-referred)");
  cmd->add_option("scene", options->scene, "Built-in scene name or scene file")->capture_default_str();
  cmd->add_option("-o,--output", options->outputs,
                  "Output image; repeat for several. The extension picks the format: .exr (32-bit float linear, in "
                  "--exr-space, with chromaticities and render metadata), .hdr (Radiance RGBE, linear, in --exr-space, "
                  "its PRIMARIES named; XYZE for the film space), or .png / .avif (display-referred, through the display "
                  "pipeline). Default: SCENE.exr and SCENE.png");
  cmd->add_option("--spp", options->spp, "Samples per pixel (passes of one sample each), at least 1")->capture_default_str();
  cmd->add_option("--max-depth", options->max_depth, "Maximum number of bounces; 1 = direct light only, 0 = emitted light only (what the camera sees of lights)")->capture_default_str();
  cmd->add_option("--seed", options->seed, "Seed of the per-pixel random streams")->capture_default_str();
  cmd->add_option("--threads", options->threads, "Worker threads (default: all cores); the image does not depend on it");
  cmd->add_option("--time-limit", options->time_limit_seconds,
                  "Stop after the pass that crosses this many seconds (0 = no limit); --spp still caps the render")
      ->capture_default_str();
  cmd->add_option("--width", options->width, "Image width in pixels (default: the scene's)");
  cmd->add_option("--height", options->height, "Image height in pixels (default: the scene's)");
  cmd->add_option("--estimator", options->estimator,
                  "Direct-light estimator: mis (NEE + BSDF sampling, power heuristic), nee (light sampling only), "
                  "bsdf (BSDF sampling only); all converge to the same image")
      ->capture_default_str();
  cmd->add_option("--normal-mapping", options->normal_mapping,
                  "Normal and bump maps: classic (shade around the mapped normal, as glTF viewers do; loses light "
                  "where it tilts) or microfacet (the mapped normal as a facet of a microsurface, Schuessler et al. "
                  "2017: energy-conserving, a different look at grazing angles); transmitting materials stay classic. "
                  "Default: the scene file's render.normal_mapping, else classic");
  cmd->add_option("--sampler", options->sampler,
                  "Random numbers of each path: independent (PCG32), sobol (padded Owen-scrambled Sobol', "
                  "stratified per pixel) or zsobol (blue-noise ordering across pixels, one layer per sample); "
                  "every choice is deterministic per (seed, pixel, sample, dimension)")
      ->capture_default_str();
  cmd->add_option("--integrator", options->integrator,
                  "wavefront (the fast one) or reference (one sample and one ray at a time, the textbook "
                  "algorithm the wavefront integrator is tested against; same image in expectation, much slower)")
      ->capture_default_str();
  cmd->add_option("--simd", options->simd,
                  "SIMD the fast paths may use: auto (the widest this processor runs), avx512, avx2, sse2 or "
                  "scalar; every level renders the same image, bit for bit (for comparisons and older processors)")
      ->capture_default_str();
  cmd->add_option("--mode", options->mode,
                  "Transport: spectral (N wavelengths per path, film in CIE XYZ) or rgb (in --working-space)")
      ->capture_default_str();
  cmd->add_option("--wavelengths", options->wavelengths, "Spectral: wavelengths per path, 3, 4 or 8")->capture_default_str();
  cmd->add_option("--wavelength-sampling", options->wavelength_sampling,
                  "Spectral: hero (uniform, Wilkie 2014), cosh (Radziszewski 2009) or cosh3 (three cosh lobes)")
      ->capture_default_str();
  cmd->add_flag("--wavelength-stratification", options->wavelength_stratification,
                "Spectral: stratify samples' wavelengths in nine strata, the middle one first: with "
                "--wavelength-sampling cosh3 a pixel's first sample then lands near 600/535/445 nm (the seed "
                "renderer's fast-colour preview); biased by up to one stratum's share until the pixel's sample "
                "count is a multiple of nine");
  cmd->add_option("--upsampling", options->upsampling,
                  "Spectral: reflectance upsampling, jakob-hanika (2019) or mallett-yuksel (2019)")
      ->capture_default_str();
  cmd->add_option("--working-space", options->working_space,
                  "srgb, acescg or rec2020: the RGB transport space, and the space of the EXR output")
      ->capture_default_str();
  cmd->add_option("--samples-per-pass", options->samples_per_pass,
                  "Samples per pixel per pass (default: sized to about 0.5 s); does not change the image");
  cmd->add_option("--exr-space", options->exr_space,
                  "EXR and .hdr pixel space: working (the working space's RGB) or film (CIE XYZ relative to E for "
                  "spectral renders); the EXR's chromaticities and the .hdr's header always say which")
      ->capture_default_str();
  cmd->add_option("--camera", options->camera,
                  "Which of the scene file's cameras renders: its name, or its zero-based index (`prism info SCENE` "
                  "lists them); default: the first");
  cmd->add_option("--variant", options->material_variant,
                  "Which of a glTF file's material variants (KHR_materials_variants) the meshes wear, by name "
                  "(`prism info SCENE` lists them); default: each mesh's own material");
  cmd->add_option("--camera-json", options->camera_json,
                  "Camera from a JSON snippet {\"eye\", \"target\", \"up\", \"fov_degrees\"} (as `prism view` saves it); "
                  "missing fields keep the scene camera's values");
  add_display_options(cmd, options->display);
  cmd->add_option("--sample-range", options->sample_range,
                  "Render only sample indices START..END-1 (e.g. 0:32), for splitting one image over several "
                  "machines; combine the EXRs with `prism merge`. Replaces --spp");
  cmd->add_option("--checkpoint", options->checkpoint,
                  "Write the film state to FILE every --checkpoint-every seconds and when the render ends or is "
                  "interrupted (atomically: an interruption never corrupts it)");
  cmd->add_option("--checkpoint-every", options->checkpoint_every_seconds, "Seconds between checkpoints")
      ->capture_default_str();
  cmd->add_option("--resume", options->resume,
                  "Continue from a checkpoint of the same scene and settings up to --spp; the result is identical "
                  "to an uninterrupted render. The checkpoint keeps being updated unless --checkpoint is given");
  cmd->add_option("--memory-limit", options->memory_limit,
                  "Refuse a render whose estimated memory (film, path pool, textures, meshes) exceeds this many "
                  "bytes; suffixes K, M, G, T (binary), e.g. 8G. Default: 90 % of physical memory");
  cmd->add_option("--aov", options->aovs,
                  "Extra EXR layers about the first surface each camera ray hits, comma-separated: albedo "
                  "(albedo.R/G/B, base colour in the EXR's colour space), normal (N.x/N.y/N.z, world-space shading "
                  "normal) and depth (Z, distance along the camera ray in scene units, +inf for misses; with "
                  "Z.coverage, the fraction of samples that hit); variance (variance.R/G/B, variance of the beauty's pixel "
                  "mean in the EXR's colour space, per channel); sample-count (sampleCount, the number of samples in each pixel's "
                  "mean, as float: where --noise-threshold spent them). The beauty stays in R, G, B; PNG and AVIF outputs "
                  "hold the beauty only (--view normal turns the normal AOV on and shows it)");
  cmd->add_option("--noise-threshold", options->adaptive.noise_threshold,
                  "Adaptive sampling (docs/adaptive-sampling.md): a pixel stops taking samples once the relative "
                  "standard error of its mean luminance, sqrt(Var[mean Y]) / max(mean Y, 0.1 x the image's mean "
                  "luminance), is at most this (e.g. 0.05) and so is every neighbour's; decided after "
                  "--adaptive-min-samples samples and every as many after; --spp stays the cap. 0 = off (every pixel "
                  "takes every sample). Keeps the variance AOV; not with --sample-range")
      ->capture_default_str();
  cmd->add_option("--adaptive-min-samples", options->adaptive.min_samples,
                  "With --noise-threshold: samples every pixel takes before the first decision, and the spacing "
                  "of later decisions (at least 2)")
      ->capture_default_str();
  cmd->add_flag("--denoise", options->denoise,
                "Denoise the beauty (non-local means guided by albedo, normal, depth and variance; docs/denoising.md): "
                "EXR, .hdr, PNG and AVIF outputs show the denoised image, the EXR keeps the noisy one as noisy.R/G/B "
                "and the AOVs it used. Turns those four AOVs on");
  cmd->add_flag("--allow-external-paths", options->allow_external_paths,
                "Let the scene file refer to files outside its own folder (absolute paths, '..')");
  add_environment_options(cmd, options->environment);
  cmd->callback([options, cmd, &action] {
    options->threads_given = cmd->count("--threads") > 0;
    options->spp_given = cmd->count("--spp") > 0;
    options->max_depth_given = cmd->count("--max-depth") > 0;
    action = [options] { return run_render(*options); };
  });
}

}  // namespace prism::cli
