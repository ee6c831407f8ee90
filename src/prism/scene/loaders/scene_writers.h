#pragma once
// Writing a Scene back out, for generated scenes (`prism generate`) that other renderers
// should render too: Prism's JSON (prism-scene/1) and the pbrt-v4 subset the pbrt loader
// reads. Both write meshes inline (pbrt: trianglemesh), materials, emitters, the camera,
// the environment colour and the render defaults. Textures are written as PNG files next
// to the scene, "<stem>-<index>-<name>.png" (texture_png.h), referenced by relative name:
// JSON with base_color_texture etc. and alpha_mode/alpha_cutoff/opacity; pbrt-v4 with
// imagemap Textures (uvs written as v_pbrt = 1 − v, pbrt's v pointing up the image) and,
// for alpha-tested materials, a grey "<…>-alpha-<material>.png" float imagemap given to
// the shapes as "texture alpha" (MASK is thresholded to 0/1, since pbrt-v4's alpha is
// stochastic). Scenes with instances, punctual lights, an environment image or spectra
// given as data (scene/spectral_inputs.h) are refused (UsageError), and so are what a
// format cannot say (JSON: uv transforms; pbrt: rotated or mirrored textures, textures on
// non-diffuse materials, non-grey texture tints).
// Every file goes to a temporary file that is renamed (textures first, the scene last),
// so an interrupted write leaves no partial file.
#include <filesystem>

#include "prism/scene/scene.h"

namespace prism::loaders {

void write_scene_json(const Scene& scene, const std::filesystem::path& path);
void write_scene_pbrt(const Scene& scene, const std::filesystem::path& path);

}  // namespace prism::loaders
