#pragma once
// PNG writing with colour metadata beyond the sRGB chunk: cICP, mDCv and cLLi (PNG Third
// Edition, W3C 2025) and iCCP (an embedded ICC profile). Debian 12's libpng 1.6.39 has no API for these chunks, so they are
// written through libpng's unknown-chunk API, placed before PLTE/IDAT as the spec requires.
#include <filesystem>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "prism/io/hdr10_metadata.h"
#include "prism/io/image.h"
#include "prism/io/png.h"

namespace prism {

struct PngColorMetadata {
  bool srgb_chunk = false;  // `sRGB` (+ gAMA/cHRM fallbacks); only for sRGB-encoded Rec.709
  std::optional<CicpInfo> cicp;
  std::optional<MasteringDisplay> mastering_display;
  std::optional<ContentLightLevel> content_light_level;
  // An ICC profile for the `iCCP` chunk (empty: none); never together with srgb_chunk
  // (PNG forbids both). Readers that know cICP give it precedence over iCCP.
  std::vector<std::uint8_t> icc_profile;
  std::string icc_profile_name = "ICC profile";  // 1–79 Latin-1 characters
  std::vector<PngText> text;  // tEXt chunks, before the image data
};

// 8- or 16-bit RGB; writes atomically. Throws IoError.
void write_png_with_color_metadata(const std::filesystem::path& path, const EncodedImage& image,
                                   const PngColorMetadata& metadata);

}  // namespace prism
