#pragma once
// Overlay/UI compositing in HDR: an 8-bit sRGB RGBA overlay (captions, UI) blended with the
// tone-mapped image at the ODT's normalised linear AP1 step (AcesOutputTransform::
// normalized_ap1), with the pixel's peak luminance moved from Y_MAX toward the UI
// luminance where the overlay is opaque. With α the overlay's alpha, p the blend power:
//
//   ui   = AP1 ← Rec.709 (Bradford D65 → ACES white) of sRGB⁻¹(overlay RGB)  (IEC 61966-2-1)
//   w    = α^p        when Y_MAX ≥ UI   (the background dims only under nearly opaque UI)
//   w    = α^(1/p)    when Y_MAX < UI   (inverted power: translucent UI reaches its level)
//   Y'   = Y_MAX + w · (UI − Y_MAX)                                   the pixel's peak, nits
//   c    = (1 − α) · bg · min(1, Y_MAX / Y') + α · ui                  normalised AP1
//   L    = ODT_display(c) · Y'                                         display light, nits
//
// So the UI shows at UI nits where opaque, and the background's light (1 − α)·bg·min(Y', Y_MAX)
// is never brighter than without the overlay, whichever side of UI the display peak lies.
#include <vector>

#include "prism/core/vec.h"
#include "prism/io/image.h"

namespace prism::display {

struct UiOverlay {
  int width = 0, height = 0;
  std::vector<float> ap1;    // 3 per pixel: the overlay colour, linear AP1, 1.0 = UI white
  std::vector<float> alpha;  // 1 per pixel, straight (not premultiplied)
  double ui_nits = 200.0;    // luminance of the UI's white, 80..300
  double blend_power = 5.0;  // p above, > 0
};

// From an 8-bit (or 16-bit) RGBA PNG image; UsageError unless 4 channels and the UI
// luminance is in [80, 300] nits and the power positive.
UiOverlay make_ui_overlay(const EncodedImage& rgba, double ui_nits, double blend_power);

struct UiComposite {
  Vec3d cv_ap1;       // c above
  double peak_nits;   // Y' above
};

UiComposite composite_ui(const Vec3d& background_cv_ap1, const Vec3d& ui_ap1, double alpha, double y_max_nits,
                         double ui_nits, double blend_power);

}  // namespace prism::display
