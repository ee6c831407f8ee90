#include "environment_options.h"

namespace prism::cli {

void add_environment_options(CLI::App* command, EnvironmentOverride& environment) {
  command->add_option("--environment", environment.source,
                      "Light the scene with this equirectangular environment map (.hdr/.exr linear, .png/.jpg sRGB) "
                      "or 'uniform' (a constant white sky), replacing the scene's own environment; other lights "
                      "stay. For glTF models, which carry no lights");
  command->add_option("--environment-nits", environment.luminance_nits,
                      "Luminance in nits of a map texel of 1 (or of the uniform sky)")
      ->capture_default_str();
  command->add_option("--environment-rotation", environment.rotation_degrees,
                      "Turn the environment map about the world's +y axis, in degrees")
      ->capture_default_str();
}

}  // namespace prism::cli
