#pragma once
// The display pipeline for the renderings other than ACES 1 (rendering.h): exposure → bloom
// → the film to linear Rec.709 (one 3×3, Bradford) → the rendering (AgX or PBR Neutral:
// display-linear Rec.709 relative to white) → × the target's white (100 nits) → the
// target's primaries (or the user's display, clipped to [0, white]; Rec.709 for scRGB) →
// render-scale upscale of the light → encoding. The same DisplayImage as the ACES path, so
// the writers, debug views and the viewer take either.
//
// Not for these renderings (UsageError): the ACES blue-light LMT (--blue-correction) and the
// UI overlay, which composites at the ACES ODT's normalised AP1 step.
#include "prism/color/color_space.h"
#include "prism/display/display_pipeline.h"
#include "prism/io/image.h"

namespace prism::display {

DisplayImage apply_rendering_pipeline(const ImageRgbF& film, const color::ColorSpace& film_space,
                                      const DisplaySettings& settings);

// Display-linear light relative to the display's white, in Rec.709 primaries, of one pixel
// of linear Rec.709 scene light under a rendering other than aces1.
Vec3d rendering_display_linear(Rendering rendering, const Vec3d& rec709_linear);

}  // namespace prism::display
