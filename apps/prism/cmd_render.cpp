// `prism render`: render a scene progressively and write EXR and/or PNG images.
#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "command.h"
#include "progress_reporter.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/core/version.h"
#include "prism/display/clamp_srgb_encode.h"
#include "prism/io/atomic_file.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "prism/render/checkpoint.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"

namespace prism::cli {
namespace {

struct RenderOptions {
  std::string scene = "cornell-box";
  std::vector<std::string> outputs;
  int spp = 64;
  int max_depth = 8;
  std::uint64_t seed = 0;
  int threads = 0;
  bool threads_given = false;
  double time_limit_seconds = 0.0;
  int width = 0, height = 0;  // 0: the scene's default
  std::string estimator = "mis";
  std::string sample_range;  // "START:END"
  std::string checkpoint;
  double checkpoint_every_seconds = 60.0;
  std::string resume;
  bool spp_given = false;
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

enum class OutputFormat { exr, png };

OutputFormat output_format(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".exr" || ext == ".EXR") return OutputFormat::exr;
  if (ext == ".png" || ext == ".PNG") return OutputFormat::png;
  throw UsageError(fmt::format("unknown output extension '{}' in '{}' (supported: .exr, .png)", ext, path.string()));
}

LightEstimator parse_estimator(const std::string& name) {
  if (name == "mis") return LightEstimator::mis;
  if (name == "nee") return LightEstimator::nee_only;
  if (name == "bsdf") return LightEstimator::bsdf_only;
  throw UsageError(fmt::format("unknown --estimator '{}' (mis, nee, bsdf)", name));
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

ExrChromaticities film_chromaticities() {
  // The foundation's film holds linear Rec.709/sRGB primaries with a D65 white.
  const color::ColorSpace& s = color::color_space("srgb");
  auto f = [](double v) { return static_cast<float>(v); };
  return {f(s.red.x), f(s.red.y), f(s.green.x), f(s.green.y), f(s.blue.x), f(s.blue.y), f(s.white.x), f(s.white.y)};
}

std::string hex(std::uint64_t v) { return fmt::format("{:016x}", v); }

void write_outputs(const std::vector<std::filesystem::path>& outputs, const Film& film, const RenderResult& result,
                   const std::string& scene_name, const RenderSettings& settings, std::uint64_t fingerprint) {
  ImageRgbF image{film.width(), film.height(), film.mean_rgb()};
  for (const auto& path : outputs) {
    if (output_format(path) == OutputFormat::exr) {
      ExrMetadata meta;
      meta.strings["prism:version"] = kVersion;
      meta.strings["prism:scene"] = scene_name;
      meta.ints["prism:spp"] = result.passes_done;
      meta.doubles["prism:renderSeconds"] = result.elapsed_seconds;
      // What `prism merge` needs to combine partial renders of one image.
      meta.ints["prism:sampleBegin"] = settings.first_sample;
      meta.ints["prism:sampleEnd"] = result.next_sample;
      meta.strings["prism:fingerprint"] = hex(fingerprint);
      write_exr(path, image, film_chromaticities(), meta);
    } else {
      write_png(path, clamp_srgb_encode(image, 8));
    }
  }
}

int run_render(const RenderOptions& o) {
  RenderSettings settings;
  settings.samples_per_pixel = o.spp;
  settings.path.max_depth = o.max_depth;
  settings.path.estimator = parse_estimator(o.estimator);
  settings.seed = o.seed;
  settings.threads = o.threads;
  settings.time_limit_seconds = o.time_limit_seconds;
  if (o.threads_given && o.threads < 1)
    throw UsageError(fmt::format("--threads must be at least 1 (got {}; omit it to use all cores)", o.threads));
  if (o.width < 0 || o.height < 0) throw UsageError("--width and --height must be positive");

  std::vector<std::filesystem::path> outputs;
  const std::vector<std::string> names =
      o.outputs.empty() ? std::vector<std::string>{"render.exr", "render.png"} : o.outputs;
  for (const auto& n : names) outputs.emplace_back(n);
  // Check everything that can be checked before spending time on the render.
  for (const auto& p : outputs) output_format(p);
  const Scene scene = load_scene(o.scene);
  if (o.outputs.empty()) outputs = {scene.name + ".exr", scene.name + ".png"};
  for (const auto& p : outputs) check_writable_output(p);
  settings.width = o.width > 0 ? o.width : scene.default_width;
  settings.height = o.height > 0 ? o.height : scene.default_height;
  if (!o.sample_range.empty()) {
    if (o.spp_given) throw UsageError("give either --spp or --sample-range, not both");
    apply_sample_range(o.sample_range, settings);
  }
  validate_render_settings(settings);
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
  RenderResult result = render(scene, settings, hooks, resume ? &*resume : nullptr);
  progress.finish();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);

  write_outputs(outputs, result.film, result, scene.name, settings, fingerprint);

  const double samples = static_cast<double>(result.passes_done) * result.film.pixel_count();
  std::vector<std::string> written;
  for (const auto& p : outputs) written.push_back(p.string());
  if (!checkpoint_path.empty()) written.push_back(checkpoint_path + " (checkpoint)");
  fmt::print("prism: rendered {} {}x{}, {} spp in {:.2f} s ({:.2f} M samples/s) -> {}\n", scene.name, settings.width,
             settings.height, result.passes_done, result.elapsed_seconds,
             result.elapsed_seconds > 0 ? samples / result.elapsed_seconds * 1e-6 : 0.0, fmt::join(written, ", "));
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
  CLI::App* cmd = root.add_subcommand("render", "Render a scene to EXR (linear, scene-referred) and/or PNG (sRGB)");
  cmd->add_option("scene", options->scene, "Built-in scene name or scene file")->capture_default_str();
  cmd->add_option("-o,--output", options->outputs,
                  "Output image; repeat for several. The extension picks the format: .exr (32-bit float linear "
                  "Rec.709, with chromaticities and render metadata) or .png (8-bit sRGB). Default: SCENE.exr and SCENE.png");
  cmd->add_option("--spp", options->spp, "Samples per pixel (passes of one sample each), at least 1")->capture_default_str();
  cmd->add_option("--max-depth", options->max_depth, "Maximum number of bounces; 1 = direct light only")->capture_default_str();
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
  cmd->callback([options, cmd, &action] {
    options->threads_given = cmd->count("--threads") > 0;
    options->spp_given = cmd->count("--spp") > 0;
    action = [options] { return run_render(*options); };
  });
}

}  // namespace prism::cli
