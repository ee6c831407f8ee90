// `prism denoise IN.exr -o OUT.exr`: denoises an EXR that carries the beauty's guides
// (albedo, normal, depth and variance layers, under Prism's or pbrt-v4's names; see
// denoise_exr.h and docs/denoising.md). Files without them are refused with a one-line
// error naming the missing layers, and nothing is written.
#include <chrono>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "command.h"
#include "denoise_exr.h"
#include "prism/core/error.h"
#include "prism/core/parallel.h"
#include "prism/core/version.h"
#include "prism/denoise/denoiser.h"
#include "prism/io/atomic_file.h"

namespace prism::cli {
namespace {

struct DenoiseOptions {
  std::string input;
  std::string output;
  int threads = 0;
  denoise::DenoiseSettings settings;
};

// Absent chromaticities mean Rec. ITU-R BT.709 primaries and a D65 white (OpenEXR's
// "Technical Introduction", the chromaticities attribute), which is what is written back.
ExrChromaticities rec709() { return {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f}; }

int run_denoise(const DenoiseOptions& o) {
  const std::filesystem::path out_path(o.output);
  const std::string ext = out_path.extension().string();
  if (ext != ".exr" && ext != ".EXR") throw UsageError(fmt::format("denoise writes an .exr, not '{}'", o.output));
  if (o.threads < 0) throw UsageError("--threads must be at least 1 (omit it to use all cores)");
  denoise::check_denoise_settings(o.settings);
  const ThreadLimit thread_limit(o.threads);
  check_writable_output(out_path);
  DenoiseExrInput in = read_denoise_exr(o.input);
  const auto start = std::chrono::steady_clock::now();
  const ImageRgbF denoised = denoise::denoise_image(in.buffers, o.settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ExrMetadata meta = in.file.metadata;
  meta.strings["prism:denoiser"] = "nlm-features";
  meta.strings["prism:denoisedBy"] = kVersion;
  meta.doubles["prism:denoiseSeconds"] = seconds;
  std::vector<ExrChannelGroup> layers{noisy_beauty_channels(in.buffers.color)};
  for (auto& g : denoise_guide_channels(in.buffers)) layers.push_back(std::move(g));
  write_exr(out_path, denoised, in.file.has_chromaticities ? in.file.chromaticities : rec709(), meta, {}, layers);
  fmt::print("prism: denoised {} ({}x{}) in {:.2f} s -> {}\n", o.input, denoised.width, denoised.height, seconds,
             o.output);
  return 0;
}

}  // namespace

void add_denoise_command(CLI::App& root, Action& action) {
  auto o = std::make_shared<DenoiseOptions>();
  CLI::App* cmd = root.add_subcommand(
      "denoise",
      "Denoise an EXR render that carries albedo, normal, depth and variance layers (Prism's, or pbrt-v4 "
      "GBufferFilm's Albedo/Ns/P/Variance); writes the denoised beauty as RGB and keeps the noisy one as noisy.R/G/B");
  cmd->add_option("input", o->input, "Input EXR")->required();
  cmd->add_option("-o,--output", o->output, "Output EXR")->required();
  cmd->add_option("--threads", o->threads, "Worker threads (default: all cores); the image does not depend on it");
  cmd->add_option("--search-radius", o->settings.nlm.search_radius,
                  "Pixels within this many rows and columns are averaged: a (2r+1)^2 window")
      ->capture_default_str();
  cmd->add_option("--patch-radius", o->settings.nlm.patch_radius,
                  "Patches of (2f+1)^2 pixels are compared to decide how alike two pixels are")
      ->capture_default_str();
  cmd->add_option("--strength", o->settings.nlm.color_sensitivity,
                  "k_c of Rousselle et al.: larger values average pixels whose patches differ more (smoother, "
                  "less detail)")
      ->capture_default_str();
  cmd->callback([o, &action] { action = [o] { return run_denoise(*o); }; });
}

}  // namespace prism::cli
