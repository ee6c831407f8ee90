#pragma once
// A camera as a small JSON snippet, the form the viewer saves and `prism render
// --camera-json` reads:
//   {"eye": [x, y, z], "target": [x, y, z], "up": [x, y, z], "fov_degrees": 40}
// Optional thin-lens fields: "aperture_radius", "focus_distance" (scene units).
#include <filesystem>
#include <string>

#include "prism/scene/scene.h"

namespace prism {

// The snippet of `camera` (pretty-printed, one field per line).
std::string camera_to_json(const Camera& camera);

// Reads the snippet onto `base` (fields absent from the JSON keep base's values). Throws
// SceneError on malformed JSON, wrong types, non-finite numbers, eye == target, a zero or
// parallel up vector or a field of view outside (0, 180).
Camera camera_from_json(const std::string& text, const Camera& base = {});

// File versions. write_camera_json writes atomically; both throw IoError on I/O failure.
Camera read_camera_json(const std::filesystem::path& path, const Camera& base = {});
void write_camera_json(const std::filesystem::path& path, const Camera& camera);

}  // namespace prism
