#pragma once
// OpenEXR headers walked by Prism before OpenEXR reads them (OpenEXR file layout: magic,
// version, then attributes `name\0 type\0 int32 size, value` until an empty name), because
// OpenEXR 3.1 allocates an attribute's declared size, and the chunk offset table for the
// declared data window, before noticing the file is shorter (found by the image-reader fuzz
// target: a 610-byte file asking for 2 GB). Checks that every attribute fits in the file,
// that the data window is within the size limit and that a tiled image's offset table
// (8 bytes per level-0 tile) fits in the file.
//
// Every OpenEXR Prism reads goes through this walk first: textures and skies
// (scene/texture_file.h), and `prism tonemap`, `merge` and `--resume` inputs (io/exr.h).
#include <filesystem>
#include <limits>
#include <span>
#include <string_view>

namespace prism {

// What a texture reads of the first part: its data window's size, and its colour
// channels: R, G and B when any of them is listed (3; a missing one reads as 0), else Y,
// luminance (1), else none (0); `half` when all of those are HALF at full resolution, so
// their 16 bits can be kept.
struct OpenExrFirstPart {
  long width = 0, height = 0;
  int channels = 0;
  bool half = false;
};

// Throws IoError "cannot read image '<name>': corrupt or truncated OpenEXR header (<why>)"
// for a header OpenEXR would misread or allocate for beyond the file, and the size errors of
// check_image_dimensions for a data window outside 1..max_dimension.
OpenExrFirstPart check_openexr_header(std::span<const unsigned char> bytes, int max_dimension,
                                      std::string_view name);

// The same for a file: its first MiB is walked, or the whole file where a header runs past
// that. Throws IoError for a file that cannot be read.
OpenExrFirstPart check_openexr_file_header(const std::filesystem::path& path,
                                           int max_dimension = std::numeric_limits<int>::max());

// Throws IoError "cannot read image '<name>': invalid size WxH" for a size below 1, and
// "... WxH pixels exceeds the limit of NxN" above max_dimension: every image reader's check
// before it allocates.
void check_image_dimensions(long width, long height, int max_dimension, std::string_view name);

}  // namespace prism
