// libFuzzer target: the texture image readers (PNG and JPEG through stb_image, Radiance .hdr
// through scene/radiance_hdr.h, OpenEXR through prism::read_exr, which needs a file). The
// size limit is lowered so that headers claiming huge images are refused rather than
// exhausting the fuzzer's memory. Images are read as colour textures in their own gamut, so
// that the conversions from a file's primaries (and a Radiance header's factors) run too.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>

#include "prism/core/error.h"
#include "prism/scene/texture_file.h"

namespace {
constexpr int kMaxDimension = 2048;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const unsigned char> bytes(data, size);
  try {
    if (prism::detect_image_format(bytes) == prism::ImageFileFormat::openexr) {
      static const std::filesystem::path path =
          std::filesystem::temp_directory_path() / ("prism_fuzz_image_" + std::to_string(::getpid()) + ".exr");
      std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                    static_cast<std::streamsize>(size));
      prism::read_texture_file(path, prism::TextureEncoding::srgb, kMaxDimension, prism::TextureContent::color_own_gamut);
    } else {
      prism::decode_texture_memory(bytes, "fuzz", prism::TextureEncoding::srgb, kMaxDimension,
                                   prism::TextureContent::color_own_gamut);
    }
  } catch (const prism::Error&) {
  }
  return 0;
}
