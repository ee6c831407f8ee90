#include "prism/display/ocio_display.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cmath>
#include <exception>

#include "prism/core/error.h"

namespace OCIO = OCIO_NAMESPACE;

namespace prism::display {
namespace {

OCIO::ConstConfigRcPtr load_config(const std::string& path) {
  if (path.empty()) throw UsageError("no OCIO config: give --ocio-config FILE or set $OCIO");
  return OCIO::Config::CreateFromFile(path.c_str());
}

OcioDisplayView resolve(const OCIO::Config& config, const OcioDisplaySettings& s) {
  const std::string display = s.display.empty() ? config.getDefaultDisplay() : s.display;
  bool known = false;
  for (int i = 0; i < config.getNumDisplays(); ++i) known |= display == config.getDisplay(i);
  if (!known) throw UsageError("OCIO config has no display '" + display + "'");
  const std::string view = s.view.empty() ? config.getDefaultView(display.c_str()) : s.view;
  known = false;
  for (int i = 0; i < config.getNumViews(display.c_str()); ++i) known |= view == config.getView(display.c_str(), i);
  if (!known) throw UsageError("OCIO display '" + display + "' has no view '" + view + "'");
  return {display, view};
}

}  // namespace

OcioDisplayView resolve_ocio_display_view(const OcioDisplaySettings& s) {
  try {
    return resolve(*load_config(s.config_path), s);
  } catch (const OCIO::Exception& e) {
    throw UsageError(std::string("OpenColorIO: ") + e.what());
  }
}

DisplayImage apply_ocio_display(const ImageRgbF& film, double exposure_scale, const OcioDisplaySettings& s) {
  DisplayImage out;
  out.width = film.width;
  out.height = film.height;
  out.encoding = DisplayEncoding::srgb;
  out.primaries = "srgb";
  out.exposure_scale = exposure_scale;
  try {
    OCIO::ConstConfigRcPtr config = load_config(s.config_path);
    const auto [display, view] = resolve(*config, s);
    const std::string input = s.input_space.empty() ? std::string(OCIO::ROLE_SCENE_LINEAR) : s.input_space;
    OCIO::DisplayViewTransformRcPtr t = OCIO::DisplayViewTransform::Create();
    t->setSrc(input.c_str());
    t->setDisplay(display.c_str());
    t->setView(view.c_str());
    OCIO::ConstCPUProcessorRcPtr cpu = config->getProcessor(t)->getDefaultCPUProcessor();
    out.code.resize(film.rgb.size());
    for (std::size_t i = 0; i < film.rgb.size(); ++i) {
      const float v = film.rgb[i];
      out.code[i] = std::isfinite(v) ? static_cast<float>(v * exposure_scale) : 0.0f;
    }
    OCIO::PackedImageDesc desc(out.code.data(), film.width, film.height, 3);
    cpu->apply(desc);
  } catch (const OCIO::Exception& e) {
    throw UsageError(std::string("OpenColorIO: ") + e.what());
  }
  return out;
}

}  // namespace prism::display
