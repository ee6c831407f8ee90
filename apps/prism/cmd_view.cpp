// `prism view`: the interactive viewer (src/prism/viewer/, docs/viewer.md).
#include <memory>

#include "command.h"
#include "environment_options.h"
#include "prism/viewer/viewer_app.h"

namespace prism::cli {

void add_view_command(CLI::App& root, Action& action) {
  auto o = std::make_shared<viewer::ViewerOptions>();
  CLI::App* cmd = root.add_subcommand("view", "Open a scene in the interactive viewer (progressive rendering, live camera "
                                              "and display controls)");
  cmd->add_option("scene", o->scene, "Built-in scene name or scene file")->capture_default_str();
  cmd->add_option("--camera", o->camera,
                  "Start from this camera of the scene file: its name or zero-based index (default: the first)");
  cmd->add_option("--variant", o->material_variant,
                  "Wear this material variant of a glTF file (KHR_materials_variants; `prism info SCENE` lists them)");
  cmd->add_option("--frames", o->frames,
                  "Render this many passes, then exit (with --screenshot: write what the window shows first)");
  cmd->add_option("--screenshot", o->screenshot, "With --frames: PNG of the window, UI included");
  cmd->add_option("--ev100", o->ev100,
                  "Initial exposure (EV100); default: the scene camera's, else metered as render meters it "
                  "(docs/display-pipeline.md), adapting smoothly as the view changes");
  cmd->add_option("--rendering", o->rendering,
                  "Initial rendering: aces1, aces2, agx or pbr-neutral (default aces1; see prism tonemap --help)");
  cmd->add_option("--odt", o->odt, "Initial output transform (see prism tonemap --help)")->capture_default_str();
  cmd->add_option("--view", o->view,
                  "Initial debug view: normal (shading-normal AOV as 0.5 + 0.5·N), luminance, luminance-display, "
                  "gamut-clip, sdr-hdr-split, chromaticity, bloom (the bloom component alone)");
  cmd->add_option("--mode", o->mode, "Initial transport: spectral or rgb")->capture_default_str();
  cmd->add_option("--sampler", o->sampler, "Random numbers of each path: independent, sobol or zsobol (default: as render)");
  cmd->add_option("--normal-mapping", o->normal_mapping,
                  "Initial normal-map model: classic or microfacet (default: the scene file's, else classic; see "
                  "prism render --help)");
  cmd->add_option("--samples-per-pass", o->samples_per_pass, "Samples per pixel per displayed pass")
      ->capture_default_str();
  cmd->add_option("--bounces-per-pass", o->bounces_per_pass,
                  "Show the film every N bounces of the paths in flight, not only after whole passes (the "
                  "seed's #Bounce/Frame; 0: off). Never changes the converged image")
      ->capture_default_str();
  cmd->add_option("--max-depth", o->max_depth,
                  "Maximum number of bounces (0: emitted light only); default: the scene file's, else 64, as render");
  cmd->add_option("--threads", o->threads, "Worker threads for loading, preparing and rendering (default: all cores)");
  cmd->add_option("--resolution-scale", o->resolution_scale, "Film size as a fraction of the window, 0.125..1")
      ->capture_default_str();
  cmd->add_option("--width", o->window_width, "Window width (screen coordinates)")->capture_default_str();
  cmd->add_option("--height", o->window_height, "Window height (screen coordinates)")->capture_default_str();
  cmd->add_flag("--log-events", o->log_events,
                "Print one line per event (restart, camera, pass, screenshot, UI frame times) on stdout");
  cmd->add_flag("--allow-external-paths", o->allow_external_paths,
                "Let the scene file refer to files outside its own folder");
  add_environment_options(cmd, o->environment);
  cmd->callback([o, &action] { action = [o] { return viewer::run_viewer(*o); }; });
}

}  // namespace prism::cli
