#pragma once
// Image resampling for the display pipeline: the bilinear upscale of `--render-scale`
// (render at a fraction of the output size, show at full size) and the 2×2 box
// downsample of the bloom's mip chain. Pixel centres sit at (i + 0.5) in both images, so
// an image and its resampled version cover the same area.
#include "prism/io/image.h"

namespace prism::display {

// Bilinear interpolation of the four nearest source pixels at each output pixel centre,
// clamped to the edge. Any output size ≥ 1; for 2× it preserves the mean of the interior.
ImageRgbF upscale_bilinear(const ImageRgbF& image, int width, int height);

// Output size for rendering at `render_scale` of it: round(size / render_scale). The
// scale must lie in (0, 1]; UsageError otherwise.
int upscaled_size(int render_size, double render_scale);

// Mean of each 2×2 block (odd sizes: the last row/column folds into the previous block),
// size ceil(w/2)×ceil(h/2). Preserves the image's sum × 1/4 (its mean × area).
ImageRgbF downsample_box2(const ImageRgbF& image);

}  // namespace prism::display
