#include "prism/viewer/viewer_state.h"

namespace prism::viewer {

display::DisplaySettings resolved_display_settings(const DisplayControls& c) {
  display::DisplaySettings s = c.settings;
  s.auto_exposure = c.auto_exposure;
  s.auto_exposure_key = c.auto_exposure_key;
  s.exposure_ev100 = c.auto_exposure ? std::nullopt : std::optional<double>(c.ev100);
  return s;
}

bool hdr_output(const DisplayControls& c) { return display::odt_description(c.settings.odt).hdr; }

}  // namespace prism::viewer
