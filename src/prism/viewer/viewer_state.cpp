#include "prism/viewer/viewer_state.h"

#include "prism/render/first_picture.h"

namespace prism::viewer {

InitialControls initial_controls(const Scene& scene) {
  const FirstPicture first = first_picture_defaults(scene);
  InitialControls c;
  RenderSettings& s = c.render.settings;
  s.width = first.width;
  s.height = first.height;
  s.path = first.path;
  s.transport = first.transport;
  s.samples_per_pass = 1;
  s.aovs.normal = true;
  s.aovs.depth = true;
  c.render.camera = first.camera;
  c.render.materials = scene.materials;
  c.render.lights = scene.lights;
  c.display.metering = first.metering;
  c.display.auto_exposure_key = first.metering.key;
  if (first.camera_ev100) {
    c.display.auto_exposure = false;
    c.display.ev100 = *first.camera_ev100;
  }
  return c;
}

display::DisplaySettings resolved_display_settings(const DisplayControls& c) {
  display::DisplaySettings s = c.settings;
  // Auto exposure is metered by the display thread (display_worker.cpp) with the film's
  // coverage and adapted over time; the pipeline then gets the EV it chose.
  s.auto_exposure = c.auto_exposure;
  s.auto_exposure_key = c.auto_exposure_key;
  s.exposure_ev100 = c.auto_exposure ? std::nullopt : std::optional<double>(c.ev100);
  return s;
}

bool hdr_output(const DisplayControls& c) { return display::odt_description(c.settings.odt).hdr; }

}  // namespace prism::viewer
