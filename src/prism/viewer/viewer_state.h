#pragma once
// What the viewer's controls edit, as plain data: the render side (anything that changes
// the film and so restarts accumulation) and the display side (applied to the current
// film). The panels fill these the same way the CLI fills RenderSettings/DisplaySettings.
#include <cstdint>
#include <string>
#include <vector>

#include "prism/display/debug_views.h"
#include "prism/display/display_pipeline.h"
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
  bool auto_exposure = true;
  double auto_exposure_key = 0.18;
  display::DisplaySettings settings;  // exposure fields are filled from the two above
  display::DebugView view = display::DebugView::none;
  double sdr_white_nits = 200.0;    // sdr-hdr-split view
  // HDR10 metadata written with PQ PNGs; 0 = the default (ODT peak/black, measured CLL/FALL).
  double mastering_max_nits = 0, mastering_min_nits = 0, max_cll_nits = 0, max_fall_nits = 0;
  double ui_nits = 200.0, ui_blend_power = 5.0;  // HDR UI compositing (display/ui_overlay.h)
};

// The display settings with exposure resolved from the controls.
display::DisplaySettings resolved_display_settings(const DisplayControls& controls);

// True when the ODT is an HDR one: the UI is then composited by display/ui_overlay.h.
bool hdr_output(const DisplayControls& controls);

}  // namespace prism::viewer
