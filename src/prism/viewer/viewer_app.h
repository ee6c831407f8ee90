#pragma once
// `prism view`: the interactive viewer's entry point (see docs/viewer.md).
#include <optional>
#include <string>

#include "prism/scene/environment_override.h"

namespace prism::viewer {

struct ViewerOptions {
  std::string scene = "cornell-box";
  bool allow_external_paths = false;
  std::string camera;              // --camera NAME|INDEX of the scene file's cameras
  std::string material_variant;    // --variant NAME of a glTF file's material variants
  EnvironmentOverride environment; // --environment FILE|uniform (replaces the scene's)
  int window_width = 1280, window_height = 720;
  int frames = 0;                  // > 0: render this many passes, then exit (headless use)
  std::string screenshot;          // with frames: write what the window shows (PNG)
  std::optional<double> ev100;     // initial exposure; none: auto exposure
  std::string rendering;           // initial rendering (display/rendering.h); empty: the default
  std::string odt = "srgb-100nit";
  std::string view;                // initial debug view (display/debug_views.h); empty: none
  std::string mode = "spectral";   // spectral | rgb
  std::string sampler;             // independent | sobol | zsobol; empty: the renderer's default
  std::string normal_mapping;      // classic | microfacet; empty: the scene's choice, else classic
  int samples_per_pass = 1;
  int bounces_per_pass = 0;        // > 0: show the film every N bounces inside a pass
  std::optional<int> max_depth;    // none: the first picture's (render/first_picture.h)
  int threads = 0;
  double resolution_scale = 1.0;
  bool log_events = false;         // one line per event on stdout (tests, scripting)
};

// Opens the window and runs until it is closed (or `frames` passes are done). Returns the
// exit status. Throws NoDisplayError (viewer_window.h) without a display, and the library's
// typed errors for bad scenes or options.
int run_viewer(const ViewerOptions& options);

}  // namespace prism::viewer
