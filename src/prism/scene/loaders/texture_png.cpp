#include "prism/scene/loaders/texture_png.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <stb_image_write.h>

#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/scene/emission.h"

namespace prism::loaders {
namespace {

std::uint8_t linear_code(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(static_cast<double>(v), 0.0, 1.0) * 255.0));
}

std::uint8_t srgb_code(float v) {
  return static_cast<std::uint8_t>(std::lround(color::srgb_encode(std::clamp(static_cast<double>(v), 0.0, 1.0)) * 255.0));
}

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<unsigned char>*>(context);
  const auto* bytes = static_cast<const unsigned char*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

std::vector<unsigned char> encode_codes(const std::vector<std::uint8_t>& codes, int width, int height, int channels,
                                        const std::string& name) {
  std::vector<unsigned char> png;
  if (!stbi_write_png_to_func(&append_bytes, &png, width, height, channels, codes.data(), width * channels))
    throw IoError(fmt::format("cannot encode texture '{}' as PNG", name));
  return png;
}

void check_image(const TextureImage& image) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
      image.sample_count() != static_cast<std::size_t>(image.width) * image.height * image.channels)
    throw UsageError(fmt::format("texture '{}': not a 1- to 4-channel image", image.name));
}

}  // namespace

std::vector<unsigned char> encode_texture_png(const TextureImage& image, TextureEncoding encoding) {
  check_image(image);
  const int c = image.channels;
  std::vector<std::uint8_t> codes(image.sample_count());
  const auto code = [&](std::size_t i, float v) {
    const bool alpha = is_alpha_channel(static_cast<int>(i % static_cast<std::size_t>(c)), c);
    return alpha || encoding == TextureEncoding::linear ? linear_code(v) : srgb_code(v);
  };
  if (c >= 3 && image.texel_space != ColorPickerSpace::srgb) {
    // A PNG's texels are read back as Rec.709: an OpenEXR held in a wide-gamut material's
    // space (texture.h) goes back to Rec.709, what lies outside it clipped like what lies
    // above 1 (8-bit PNG holds neither).
    const Mat3& to_rec709 = picker_space_conversion(image.texel_space, ColorPickerSpace::srgb);
    for (std::size_t first = 0; first < codes.size(); first += static_cast<std::size_t>(c)) {
      const Vec3d rgb = to_rec709 * Vec3d(image.value(first), image.value(first + 1), image.value(first + 2));
      for (std::size_t k = 0; k < static_cast<std::size_t>(c); ++k)
        codes[first + k] = code(first + k, k < 3 ? static_cast<float>(rgb[k]) : image.value(first + k));
    }
  } else {
    for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = code(i, image.value(i));
  }
  return encode_codes(codes, image.width, image.height, c, image.name);
}

std::vector<unsigned char> encode_texture_channel_png(const TextureImage& image, int channel) {
  check_image(image);
  if (channel < 0 || channel >= image.channels) throw UsageError(fmt::format("texture '{}' has no channel {}", image.name, channel));
  std::vector<std::uint8_t> codes(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = linear_code(image.value(i * image.channels + channel));
  return encode_codes(codes, image.width, image.height, 1, image.name);
}

std::vector<TextureEncoding> texture_encodings(const Scene& scene) {
  std::vector<TextureEncoding> encodings(scene.textures.size(), TextureEncoding::linear);
  const auto colour = [&](int t) {
    if (t >= 0 && static_cast<std::size_t>(t) < encodings.size()) encodings[static_cast<std::size_t>(t)] = TextureEncoding::srgb;
  };
  for (const Material& m : scene.materials)
    colour(m.base_color_texture), colour(m.emission.texture), colour(m.sheen_color_texture),
        colour(m.specular_color_texture);
  return encodings;
}

std::string texture_file_name(const std::filesystem::path& scene_path, const TextureImage& image, std::size_t index,
                              const std::string& suffix) {
  std::string name = std::filesystem::path(image.name).stem().string();
  for (char& ch : name)
    if (!((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '-' || ch == '_')) ch = '_';
  return fmt::format("{}-{}{}{}{}.png", scene_path.stem().string(), index, name.empty() ? "" : "-", name, suffix);
}

void write_file_atomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporary_path(), std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw IoError(fmt::format("cannot write '{}'", path.string()));
  }
  file.commit();
}

std::vector<std::string> write_scene_textures(const Scene& scene, const std::filesystem::path& scene_path) {
  const std::vector<TextureEncoding> encodings = texture_encodings(scene);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < scene.textures.size(); ++i) {
    names.push_back(texture_file_name(scene_path, scene.textures[i], i));
    write_file_atomically(scene_path.parent_path() / names.back(), encode_texture_png(scene.textures[i], encodings[i]));
  }
  return names;
}

}  // namespace prism::loaders
