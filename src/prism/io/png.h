#pragma once
// PNG read/write through libpng (8- and 16-bit, grey/RGB/RGBA).
#include <filesystem>
#include <string>
#include <vector>

#include "prism/io/image.h"

namespace prism {

// One uncompressed `tEXt` chunk (PNG §11.3.4.3): keyword of 1–79 Latin-1 characters, any
// text; Prism's own keywords start with "prism:" (e.g. prism:rendering). Written by
// write_png_with_color_metadata (png_hdr.h), read back by read_png.
struct PngText {
  std::string keyword, text;
};

struct PngWriteOptions {
  bool srgb_chunk = true;  // mark the samples as sRGB-encoded (the `sRGB` chunk, perceptual intent)
};

// Writes atomically (temporary file + rename). Throws IoError.
void write_png(const std::filesystem::path& path, const EncodedImage& image, const PngWriteOptions& options = {});

struct PngFile {
  EncodedImage image;
  bool has_srgb_chunk = false;
  std::vector<PngText> text;  // the tEXt/zTXt/iTXt chunks before the image data
};

// Reads a PNG, expanding palettes and sub-byte depths to 8 bits. Throws IoError.
PngFile read_png(const std::filesystem::path& path);

}  // namespace prism
