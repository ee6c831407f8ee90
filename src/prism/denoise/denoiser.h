#pragma once
// Prism's denoiser: non-local means with feature buffers (nlm_filter.h, after Rousselle,
// Manzi and Zwicker 2013) applied to albedo-demodulated radiance (demodulation.h), guided
// by the first-hit normal, depth and albedo and by the variance of each pixel mean. It runs
// on scene-linear radiance in the beauty's own RGB space, before any display transform.
// Multithreaded on prism::parallel_for; the output is bitwise the same for any thread count.
#include "prism/denoise/feature_buffers.h"
#include "prism/denoise/nlm_filter.h"
#include "prism/io/image.h"

namespace prism::denoise {

struct DenoiseSettings {
  NlmParameters nlm;
};

// Throws UsageError for a search or patch radius outside 0..32, or a sensitivity that is not
// positive.
void check_denoise_settings(const DenoiseSettings& settings);

// The denoised beauty. Non-finite colours are treated as black with zero variance. Throws
// Error for inconsistent buffer sizes.
ImageRgbF denoise_image(const DenoiseBuffers& buffers, const DenoiseSettings& settings = {});

}  // namespace prism::denoise
