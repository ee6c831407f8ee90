#pragma once
// A Scene's textures as 8-bit PNG, for the scene writers (glTF embeds the bytes; JSON and
// pbrt-v4 write files next to the scene). Texels are linear floats in the Scene; colour
// textures are encoded with the sRGB OETF (IEC 61966-2-1), data textures and alpha
// linearly, rounded to the nearest code. Textures made from 8-bit codes and decoded as
// texture_file.h decodes them (the generated atrium's) come back bit for bit.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "prism/scene/scene.h"
#include "prism/scene/texture_file.h"

namespace prism::loaders {

// PNG bytes of `image` (1 to 4 channels: grey, grey+alpha, RGB, RGBA), deterministic.
std::vector<unsigned char> encode_texture_png(const TextureImage& image, TextureEncoding encoding);

// PNG bytes of one channel of `image` as an 8-bit grey image, linear codes (pbrt-v4's
// float "alpha" textures).
std::vector<unsigned char> encode_texture_channel_png(const TextureImage& image, int channel);

// How each texture of `scene` is encoded: sRGB when a material uses it as a colour (base
// colour, emission), linear otherwise (data and environment textures).
std::vector<TextureEncoding> texture_encodings(const Scene& scene);

// "<scene stem>-<index>-<name>.png", the name reduced to letters, digits, '-' and '_':
// deterministic, and next to the scene file so relative references resolve.
std::string texture_file_name(const std::filesystem::path& scene_path, const TextureImage& image, std::size_t index,
                              const std::string& suffix = "");

// Writes `bytes` to `folder / name` atomically (temporary file + rename). Throws IoError.
void write_file_atomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

// Writes every texture of `scene` as PNG next to `scene_path` (atomically); returns the
// file names, relative to the scene's folder, in texture order.
std::vector<std::string> write_scene_textures(const Scene& scene, const std::filesystem::path& scene_path);

}  // namespace prism::loaders
