#pragma once
// An alternative to the built-in ACES path: a studio's OpenColorIO config
// (`--ocio-config FILE --display NAME --view NAME`; with no file, the config named by $OCIO,
// as OCIO::GetCurrentConfig does). The film, after exposure, is taken to be in the config's
// input colour space (default: its `scene_linear` role) and run through the config's
// display/view processor; the result is the display's code values, as OCIO defines them.
#include <string>

#include "prism/display/display_pipeline.h"

namespace prism::display {

struct OcioDisplaySettings {
  std::string config_path;   // empty: $OCIO
  std::string display, view; // empty: the config's default display / its default view
  std::string input_space;   // empty: the scene_linear role
};

// Code values (3 per pixel, as OCIO returns them) in DisplayImage::code; `nits` is empty
// (OCIO does not say what light its displays show) and the encoding is marked srgb so that
// integer quantisation applies. Bad config, display or view: UsageError.
DisplayImage apply_ocio_display(const ImageRgbF& film, double exposure_scale, const OcioDisplaySettings& settings);

}  // namespace prism::display
