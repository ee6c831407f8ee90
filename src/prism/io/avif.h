#pragma once
// AVIF output through libavif (Debian 12: 0.11): 10- or 12-bit RGB stored as 4:4:4 with
// identity matrix coefficients (RGB in the planes, losslessly coded), tagged with CICP
// colour primaries / transfer characteristics (ITU-T H.273) in the `colr` nclx box.
// libavif 0.11 has no API for the content light level (`clli`) or mastering display
// (`mdcv`) boxes — they arrived in libavif 1.0 — so HDR AVIFs carry CICP only.
#include <cstdint>
#include <filesystem>

#include "prism/io/hdr10_metadata.h"
#include "prism/io/image.h"

namespace prism {

// image: 3 channels, bit_depth 10 or 12. Writes atomically. Throws IoError (UsageError for
// a wrong bit depth or channel count).
void write_avif(const std::filesystem::path& path, const EncodedImage& image, const CicpInfo& cicp);

struct AvifInfo {
  int width = 0, height = 0, bit_depth = 0;
  CicpInfo cicp{};
  bool yuv444 = false;
};

// The header of an AVIF file, decoded by libavif. Throws IoError.
AvifInfo read_avif_info(const std::filesystem::path& path);

// Decodes the samples too (3 channels at the file's depth). Throws IoError.
EncodedImage read_avif(const std::filesystem::path& path);

}  // namespace prism
