// libFuzzer target: the texture image readers (PNG and JPEG through stb_image, Radiance .hdr
// through io/radiance_hdr_reader.h, OpenEXR through prism::read_exr, which needs a file). The
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
#include <system_error>

#include "prism/core/error.h"
#include "prism/scene/texture_file.h"

namespace {

constexpr int kMaxDimension = 2048;

// The input written to a file of this process's own for OpenEXR, which reads files; removed
// when the input has been read, however the read ends, so that no run leaves it behind.
class ScratchFile {
 public:
  explicit ScratchFile(std::span<const unsigned char> bytes)
      : path_(std::filesystem::temp_directory_path() / ("prism_fuzz_image_" + std::to_string(::getpid()) + ".exr")) {
    std::ofstream(path_, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const unsigned char> bytes(data, size);
  try {
    if (prism::detect_image_format(bytes) == prism::ImageFileFormat::openexr) {
      const ScratchFile file(bytes);
      prism::read_texture_file(file.path(), prism::TextureEncoding::srgb, kMaxDimension,
                               prism::TextureContent::color_own_gamut);
    } else {
      prism::decode_texture_memory(bytes, "fuzz", prism::TextureEncoding::srgb, kMaxDimension,
                                   prism::TextureContent::color_own_gamut);
    }
  } catch (const prism::Error&) {
  }
  return 0;
}
