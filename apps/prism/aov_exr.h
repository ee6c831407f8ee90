#pragma once
// AOV layers (render/aov.h) in Prism's EXRs, beside the beauty's default-layer R, G, B,
// which stay unchanged so every reader still sees the image. Channel names follow the
// OpenEXR layer convention "layer.channel" (Technical Introduction to OpenEXR, "Layers",
// https://openexr.com/en/latest/TechnicalIntroduction.html) and the standard names:
//   albedo.R, albedo.G, albedo.B   albedo, in the EXR's colour space (like the beauty)
//   N.x, N.y, N.z                  world-space shading normal (what `prism tonemap --view
//                                  normal` reads)
//   Z                              depth: distance from the viewer, as the Z channel of
//                                  "Interpreting OpenEXR Deep Pixels" defines it
//                                  (https://openexr.com/en/latest/InterpretingDeepPixels.html);
//                                  +inf where no sample hit a surface
//   Z.coverage                     fraction of the pixel's samples that hit a surface (Z
//                                  is their mean; `prism merge` weights Z by it)
//   sampleCount                    samples in the pixel's mean (float, exact below 2^24;
//                                  with --noise-threshold it differs from pixel to pixel)
#include <filesystem>
#include <vector>

#include "prism/io/exr.h"
#include "prism/render/aov_images.h"

namespace prism::cli {

std::vector<ExrChannelGroup> aov_exr_channels(const AovImages& aovs);

// The AOV layers present in `path` (an AOV counts when all its channels are there), sized
// width × height. Throws IoError.
AovImages read_aov_exr_channels(const std::filesystem::path& path, int width, int height);

}  // namespace prism::cli
