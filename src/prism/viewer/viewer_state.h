#pragma once
// What the viewer's controls edit, as plain data: the render side (anything that changes
// the film and so restarts accumulation) and the display side (applied to the current
// film). The panels fill these the same way the CLI fills RenderSettings/DisplaySettings.
#include <cstdint>
#include <string>
#include <vector>

#include "prism/display/debug_views.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/exposure_metering.h"
#include "prism/render/renderer.h"
#include "prism/scene/scene.h"

namespace prism::viewer {

struct RenderControls {
  RenderSettings settings;      // width/height are derived from the window and the scale
  double resolution_scale = 1;  // film size = window framebuffer size × this
  Camera camera;
  std::vector<Material> materials;
  std::vector<Light> lights;
};

struct DisplayControls {
  double ev100 = 10.0;              // used when auto exposure is off
  bool auto_exposure = true;        // meter the film (display/exposure_metering.h), as render does
  double auto_exposure_key = 0.18;
  display::MeteringSettings metering;  // the rule; its key is auto_exposure_key
  // Eye adaptation of the shown EV toward the metered one (exposure_metering.h adapt_ev100),
  // per second: 3/s closes 95 % of a change in one second. The first frame is metered at once.
  double adaptation_speed = 3.0;
  display::DisplaySettings settings;  // exposure fields are filled from the two above
  display::DebugView view = display::DebugView::none;
  double sdr_white_nits = 200.0;    // sdr-hdr-split view
  // HDR10 metadata written with PQ PNGs; 0 = the default (ODT peak/black, measured CLL/FALL).
  double mastering_max_nits = 0, mastering_min_nits = 0, max_cll_nits = 0, max_fall_nits = 0;
};

// The controls the viewer opens a scene with, before its command-line options: the first
// picture's defaults shared with `prism render` (render/first_picture.h: camera, bounce limit,
// normal maps, transport, exposure: the scene camera's EV100, else metered with the same
// rule), one sample per pass, and the film AOVs the viewer needs: the shading normal (the
// normal view needs no restart; one surface evaluation per camera ray, 56 B a pixel) and the
// depth AOV for its coverage (which pixels see a surface: what exposure metering counts).
struct InitialControls {
  RenderControls render;
  DisplayControls display;
};
InitialControls initial_controls(const Scene& scene);

// The display settings with exposure resolved from the controls.
display::DisplaySettings resolved_display_settings(const DisplayControls& controls);

// True when the ODT is an HDR one: the window then shows its SDR preview (display_worker.h).
bool hdr_output(const DisplayControls& controls);

}  // namespace prism::viewer
