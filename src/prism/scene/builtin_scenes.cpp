#include "prism/scene/builtin_scenes.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "prism/core/error.h"

namespace prism {

std::vector<std::string> builtin_scene_names() { return {"cornell-box", "cornell-box-measured"}; }

bool is_builtin_scene(std::string_view name) {
  for (const auto& n : builtin_scene_names())
    if (n == name) return true;
  return false;
}

Scene make_builtin_scene(std::string_view name) {
  if (name == "cornell-box") return make_cornell_box();
  if (name == "cornell-box-measured") return make_cornell_box_measured();
  throw UsageError(fmt::format("unknown scene '{}' (built-in scenes: {})", name,
                               fmt::join(builtin_scene_names(), ", ")));
}

}  // namespace prism
