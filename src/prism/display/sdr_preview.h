#pragma once
// What an SDR window shows of HDR display light (the viewer, docs/viewer.md "HDR targets in
// an SDR window"): never the PQ code values, which an SDR screen shows flat and washed out.
// The viewer's ordinary image is the same rendering's SDR 100-nit target (a second run of the
// pipeline); the helpers here cover the views that are HDR images themselves.
#include "prism/display/display_pipeline.h"

namespace prism::display {

// HDR display light → an sRGB (Rec.709, 100-nit white) preview: each pixel is converted to
// Rec.709, divided by `sdr_white_nits` (diffuse white at 1) and its luminance Y compressed by
// Reinhard et al.'s extended operator Y' = Y·(1 + Y/Lw²)/(1 + Y) with Lw = the image's peak
// (white_nits) / sdr_white_nits, so that the HDR peak just reaches SDR white and highlights
// keep their gradation; chromaticity kept (RGB scaled by Y'/Y), then clipped to [0, 1].
// (Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction", eq. 4.)
DisplayImage sdr_preview_of_display_light(const DisplayImage& hdr, double sdr_white_nits);

// Pixels where `marked` differs from `unmarked` (a marking debug view such as gamut-clip on
// the HDR output) are set in a copy of `preview` to Rec.709 cyan at min(white, 100) nits.
DisplayImage transfer_marks(const DisplayImage& unmarked, const DisplayImage& marked, const DisplayImage& preview);

}  // namespace prism::display
