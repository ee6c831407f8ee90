#pragma once
// Writing a Scene back out, for generated scenes (`prism generate`) that other renderers
// should render too: Prism's JSON (prism-scene/1) and the pbrt-v4 subset the pbrt loader
// reads. Both write meshes inline (pbrt: trianglemesh), materials, emitters, the camera,
// the environment colour and the render defaults. Scenes with textures, instances or
// punctual lights are refused (UsageError): generated scenes do not use them yet.
// Writes go to a temporary file that is renamed, so an interrupted write leaves nothing.
#include <filesystem>

#include "prism/scene/scene.h"

namespace prism::loaders {

void write_scene_json(const Scene& scene, const std::filesystem::path& path);
void write_scene_pbrt(const Scene& scene, const std::filesystem::path& path);

}  // namespace prism::loaders
