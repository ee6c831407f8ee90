#pragma once
// A scene written by the writer its path's extension names (.glb, .json, else pbrt-v4) and
// loaded back as a user's `prism render` would load it: what every writer round trip needs.
#include <filesystem>

#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene.h"

namespace prism::test {

inline Scene write_and_reload(const Scene& scene, const std::filesystem::path& path) {
  if (path.extension() == ".glb") loaders::write_scene_glb(scene, path);
  else if (path.extension() == ".json") loaders::write_scene_json(scene, path);
  else loaders::write_scene_pbrt(scene, path);
  return load_scene(path.string());
}

}  // namespace prism::test
