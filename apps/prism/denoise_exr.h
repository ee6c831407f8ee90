#pragma once
// The layers `prism denoise` reads and `prism render --denoise` / `prism denoise` write
// (docs/denoising.md). Accepted input names, first match wins:
//   albedo    albedo.R/G/B (Prism)   Albedo.R/G/B (pbrt-v4 GBufferFilm)
//   normal    N.x/y/z (Prism)        Ns.X/Y/Z, N.X/Y/Z, Nsx/Nsy/Nsz (pbrt-v4, newer and older)
//   depth     Z (Prism)              P.X/Y/Z or Px/Py/Pz (pbrt-v4 camera-space position; the
//                                    distance |P| is used, 0 meaning no surface)
//   variance  variance.R/G/B (Prism: variance of the pixel mean)
//             Variance.R/G/B (pbrt-v4: the samples' variance, divided by the file's
//             samplesPerPixel attribute to give the variance of the mean)
// Output: the denoised beauty in R, G, B; the noisy beauty as noisy.R/G/B; the guides under
// Prism's names (albedo.*, N.*, Z, variance.*).
#include <filesystem>
#include <vector>

#include "prism/denoise/feature_buffers.h"
#include "prism/io/exr.h"

namespace prism::cli {

struct DenoiseExrInput {
  ExrFile file;  // the beauty, chromaticities and metadata
  denoise::DenoiseBuffers buffers;
};

// Throws IoError with a one-line message naming every missing layer.
DenoiseExrInput read_denoise_exr(const std::filesystem::path& path);

// noisy.R/G/B for the noisy beauty (interleaved RGB).
ExrChannelGroup noisy_beauty_channels(const std::vector<float>& noisy_rgb);

// albedo.*, N.*, Z and variance.* layers from denoiser input (for files that did not come
// from a Prism render, which writes its own AOV layers).
std::vector<ExrChannelGroup> denoise_guide_channels(const denoise::DenoiseBuffers& buffers);

}  // namespace prism::cli
