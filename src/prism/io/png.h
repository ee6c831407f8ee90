#pragma once
// PNG read/write through libpng (8- and 16-bit, grey/RGB/RGBA).
#include <filesystem>

#include "prism/io/image.h"

namespace prism {

struct PngWriteOptions {
  bool srgb_chunk = true;  // mark the samples as sRGB-encoded (the `sRGB` chunk, perceptual intent)
};

// Writes atomically (temporary file + rename). Throws IoError.
void write_png(const std::filesystem::path& path, const EncodedImage& image, const PngWriteOptions& options = {});

struct PngFile {
  EncodedImage image;
  bool has_srgb_chunk = false;
};

// Reads a PNG, expanding palettes and sub-byte depths to 8 bits. Throws IoError.
PngFile read_png(const std::filesystem::path& path);

}  // namespace prism
