#include "prism/scene/camera_selection.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {
namespace {

std::string describe_cameras(const Scene& scene) {
  if (scene.cameras.empty()) return "it defines no cameras (only its default view)";
  std::string out = fmt::format("it has {} camera{}:", scene.cameras.size(), scene.cameras.size() == 1 ? "" : "s");
  for (std::size_t i = 0; i < scene.cameras.size(); ++i)
    out += fmt::format(" {} '{}'", i, scene.cameras[i].name.empty() ? "unnamed" : scene.cameras[i].name);
  return out;
}

}  // namespace

void select_camera(Scene& scene, std::string_view spec) {
  if (spec.empty()) throw UsageError("--camera: empty camera name");
  // Names first: a camera may well be called "1".
  const auto by_name =
      std::find_if(scene.cameras.begin(), scene.cameras.end(), [&](const Camera& c) { return c.name == spec; });
  if (by_name != scene.cameras.end()) {
    scene.camera = *by_name;
    return;
  }
  const bool digits = std::all_of(spec.begin(), spec.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  if (digits) {
    std::size_t index = 0;
    const auto [end, ec] = std::from_chars(spec.data(), spec.data() + spec.size(), index);
    if (ec == std::errc() && end == spec.data() + spec.size() && index < scene.cameras.size()) {
      scene.camera = scene.cameras[index];
      return;
    }
    throw UsageError(fmt::format("--camera {}: no camera with that index in scene '{}'; {}", spec, scene.name,
                                 describe_cameras(scene)));
  }
  throw UsageError(fmt::format("--camera '{}': no camera of that name in scene '{}'; {}", spec, scene.name,
                               describe_cameras(scene)));
}

}  // namespace prism
