#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "prism/scene/scene.h"

namespace prism {

std::vector<std::string> builtin_scene_names();
bool is_builtin_scene(std::string_view name);
// Throws UsageError for an unknown name.
Scene make_builtin_scene(std::string_view name);

// The classic Cornell box (Cornell University Program of Computer Graphics measurements,
// in millimetres) with the camera of the Mitsuba 3 / pbrt-v4 test scenes: eye at
// (278, 273, -800) looking along +z, 39.3077° field of view.
Scene make_cornell_box();
// The same box with Cornell's measured spectra (scene/spectral_inputs.h): the walls'
// reflectances at 4 nm and the light's relative radiance, at the RGB box's luminance.
Scene make_cornell_box_measured();

}  // namespace prism
