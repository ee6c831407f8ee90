#pragma once
// The display pipeline for the renderings other than ACES 1 (rendering.h): exposure → bloom
// → the film to the rendering's input (one 3×3, Bradford: linear Rec.709 for AgX and PBR
// Neutral, ACES2065-1 for ACES 2.0) → the rendering's display light (AgX, PBR Neutral:
// Rec.709 relative to white × the target's 100 nits; ACES 2.0: nits in the target's
// primaries, Aces2OutputTransform with the target's preset) → the target's primaries (or
// the user's display, clipped to [0, peak]; Rec.709 for scRGB) →
// render-scale upscale of the light → encoding. The same DisplayImage as the ACES path, so
// the writers, debug views and the viewer take either.
//
// Not for these renderings (UsageError): the ACES blue-light LMT (--blue-correction) and the
// UI overlay, which composites at the ACES ODT's normalised AP1 step.
#include "prism/color/color_space.h"
#include "prism/display/aces2_output_transform.h"
#include "prism/display/display_pipeline.h"
#include "prism/io/image.h"

namespace prism::display {

DisplayImage apply_rendering_pipeline(const ImageRgbF& film, const color::ColorSpace& film_space,
                                      const DisplaySettings& settings);

// Display-linear light relative to the display's white, in Rec.709 primaries, of one pixel
// of linear Rec.709 scene light under agx or pbr-neutral.
Vec3d rendering_display_linear(Rendering rendering, const Vec3d& rec709_linear);

// The ACES 2.0 parameters of the settings' target (aces2_preset) with --peak-nits applied.
// UsageError for a peak outside [100, 10000].
Aces2Parameters aces2_parameters(const DisplaySettings& settings);

// ACES 2.0's inverse on a display image: code values (3 per pixel) in `encoding` for the
// settings' target (light in the target's primaries; scRGB: Rec.709 light, converted) →
// ACES2065-1 scene light. The round trip through apply_display_pipeline returns the scene
// light wherever the forward transform is invertible (inside the limiting gamut, below the
// peak).
ImageRgbF aces2_inverse(const ImageRgbF& code, DisplayEncoding encoding, const DisplaySettings& settings);

}  // namespace prism::display
