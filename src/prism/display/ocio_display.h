#pragma once
// An alternative to the built-in renderings: a studio's OpenColorIO config
// (`--ocio-config FILE --display NAME --view NAME`). The film, after exposure, is taken to be
// in the config's input colour space (default: its `scene_linear` role) and run through the
// config's display/view processor; the result is the display's code values, as OCIO defines
// them. The config is a parameter: the command line and the viewer read $OCIO, as OpenColorIO's
// own tools do, and pass it here.
#include <string>

#include "prism/display/display_pipeline.h"

namespace prism::display {

struct OcioDisplaySettings {
  std::string config_path;   // required (empty: UsageError)
  std::string display, view; // empty: the config's default display / its default view
  std::string input_space;   // empty: the scene_linear role
};

// The display and view the settings select (the config's defaults for empty names), checked
// against the config. Bad config, display or view: UsageError.
struct OcioDisplayView {
  std::string display, view;
};
OcioDisplayView resolve_ocio_display_view(const OcioDisplaySettings& settings);

// Code values (3 per pixel, as OCIO returns them) in DisplayImage::code; `nits` is empty
// (OCIO does not say what light its displays show) and the encoding is marked srgb so that
// integer quantisation applies. Bad config, display or view: UsageError.
DisplayImage apply_ocio_display(const ImageRgbF& film, double exposure_scale, const OcioDisplaySettings& settings);

}  // namespace prism::display
