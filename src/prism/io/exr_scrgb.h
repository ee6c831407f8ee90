#pragma once
// scRGB OpenEXR output: half-float linear Rec.709 RGB where 1.0 = 80 nits (IEC 61966-2-2),
// tagged with the standard `chromaticities` (Rec.709/D65) and `whiteLuminance` (80 cd/m²,
// the luminance of RGB (1, 1, 1)) attributes, so readers recover absolute light.
#include <filesystem>

#include "prism/io/exr.h"
#include "prism/io/image.h"

namespace prism {

// Writes atomically. Negative values and values above 1 are kept. Throws IoError.
void write_exr_scrgb(const std::filesystem::path& path, const ImageRgbF& scrgb, double white_luminance_nits = 80.0,
                     const ExrMetadata& metadata = {});

// The `whiteLuminance` attribute of an EXR file, or 0 when absent. Throws IoError.
double read_exr_white_luminance(const std::filesystem::path& path);

}  // namespace prism
