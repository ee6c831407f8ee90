#pragma once
// The JSON scenes under data/scenes/ that ship inside the binary as built-in scenes
// (embedded at configure time by loaders.cmake; no run-time data path).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace prism::loaders {

std::vector<std::string> embedded_scene_names();
// The JSON text of a built-in scene, or nullopt when `name` is not one.
std::optional<std::string_view> embedded_scene_json(std::string_view name);

}  // namespace prism::loaders
