#pragma once
// OpenEXR read/write of 32-bit float RGB with the `chromaticities` attribute and
// Prism's own metadata.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "prism/io/image.h"

namespace prism {

// CIE xy of the image's RGB primaries and white (the EXR `chromaticities` attribute).
struct ExrChromaticities {
  float red_x, red_y, green_x, green_y, blue_x, blue_y, white_x, white_y;
};

struct ExrMetadata {
  std::map<std::string, std::string> strings;
  std::map<std::string, int> ints;
  std::map<std::string, double> doubles;
};

enum class ExrPixelType { float32, half };

struct ExrWriteOptions {
  ExrPixelType pixel_type = ExrPixelType::float32;  // half: values beyond ±65504 become ±inf
  // The standard `whiteLuminance` attribute: nits of RGB (1, 1, 1) (e.g. 80 for scRGB).
  std::optional<double> white_luminance_nits;
};

// Channels written beside the beauty's R, G, B (AOVs), always as 32-bit float whatever
// ExrWriteOptions::pixel_type says: `names` are full OpenEXR channel names, "layer.channel"
// for a channel of a layer ("albedo.R") or a bare name for the default layer ("Z"); `pixels`
// holds names.size() interleaved values per pixel, row-major from the top-left pixel.
struct ExrChannelGroup {
  std::vector<std::string> names;
  std::vector<float> pixels;
};

// Writes atomically (temporary file + rename). Throws IoError.
void write_exr(const std::filesystem::path& path, const ImageRgbF& image,
               const ExrChromaticities& chromaticities, const ExrMetadata& metadata = {},
               const ExrWriteOptions& options = {}, const std::vector<ExrChannelGroup>& extra_channels = {});

struct ExrFile {
  ImageRgbF image;
  bool has_chromaticities = false;
  ExrChromaticities chromaticities{};
  ExrMetadata metadata;  // string, int and double attributes other than the standard ones
};

// Reads R, G, B channels (missing channels read as 0), or, in a file with none of them, Y
// into all three (grey). Throws IoError on any failure, and for a file with none of R, G,
// B, Y. The header is walked first (io/openexr_header.h): a corrupt one is refused before
// OpenEXR allocates what it declares.
ExrFile read_exr(const std::filesystem::path& path);

// The channels `names` as stored halves (IEEE binary16 bits), interleaved, width × height ×
// names.size(); nothing when any of them is missing or not HALF at full resolution.
// Throws IoError.
struct ExrHalves {
  int width = 0, height = 0;
  std::vector<std::uint16_t> values;
};
std::optional<ExrHalves> read_exr_halves(const std::filesystem::path& path, const std::vector<std::string>& names);

// The channels `names` (full names), interleaved as ExrChannelGroup::pixels, or nothing when
// the file lacks any of them. Throws IoError.
std::optional<std::vector<float>> read_exr_channels(const std::filesystem::path& path,
                                                    const std::vector<std::string>& names);

// The layer `name`.x, `name`.y, `name`.z of an EXR (e.g. the shading-normal AOV "N") as a
// three-channel image, or nothing when the file lacks any of the three. Throws IoError.
std::optional<ImageRgbF> read_exr_vector_layer(const std::filesystem::path& path, const std::string& name);

}  // namespace prism
