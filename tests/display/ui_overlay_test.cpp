// Overlay/UI compositing in HDR (display/ui_overlay.h).
#include <gtest/gtest.h>

#include <cmath>

#include "prism/core/error.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/ui_overlay.h"

namespace prism::display {
namespace {

TEST(DisplayOverlay, CompositeEnds) {
  const Vec3d bg{0.3, 0.2, 0.1}, ui{1, 1, 1};
  const UiComposite none = composite_ui(bg, ui, 0.0, 1000.0, 200.0, 5.0);
  EXPECT_EQ(none.peak_nits, 1000.0);
  EXPECT_EQ(none.cv_ap1.x, bg.x);
  const UiComposite opaque = composite_ui(bg, ui, 1.0, 1000.0, 200.0, 5.0);
  EXPECT_EQ(opaque.peak_nits, 200.0);
  EXPECT_EQ(opaque.cv_ap1.y, 1.0);
  // Half alpha on a 1000-nit display: the peak moves by 0.5^5 of the way only.
  EXPECT_NEAR(composite_ui(bg, ui, 0.5, 1000.0, 200.0, 5.0).peak_nits, 1000.0 - 800.0 / 32, 1e-9);
  // Below the UI luminance the inverted power moves it fast: 0.5^(1/5).
  EXPECT_NEAR(composite_ui(bg, ui, 0.5, 100.0, 200.0, 5.0).peak_nits, 100.0 + 100.0 * std::pow(0.5, 0.2), 1e-9);
}

TEST(DisplayOverlay, BackgroundNeverBrightens) {
  // Background light = (bg part of c) × peak must not exceed bg × Y_MAX, for any alpha, on
  // either side of the UI luminance.
  for (double y_max : {100.0, 1000.0, 4000.0})
    for (double ui_nits : {80.0, 200.0, 300.0})
      for (double a = 0.0; a <= 1.0; a += 0.05) {
        const UiComposite c = composite_ui({1, 1, 1}, {0, 0, 0}, a, y_max, ui_nits, 5.0);
        EXPECT_LE(c.cv_ap1.x * c.peak_nits, y_max * (1 + 1e-12)) << y_max << " " << ui_nits << " " << a;
      }
}

EncodedImage overlay(int w, int h, std::uint16_t grey, std::uint16_t alpha) {
  // Filled by index: GCC 12 misreports insert(end, {…}) into an empty vector as an
  // overflow (-Wstringop-overflow false positive).
  EncodedImage o{w, h, 4, 8, std::vector<std::uint16_t>(static_cast<std::size_t>(4 * w * h), grey)};
  for (std::size_t i = 3; i < o.samples.size(); i += 4) o.samples[i] = alpha;
  return o;
}

TEST(DisplayOverlay, OpaqueWhiteShowsAtUiNits) {
  // On dark, mid and very bright backgrounds, an opaque white overlay shows at --ui-nits on
  // a 1000-nit HDR output, and a transparent one leaves the image as it was.
  for (float bg : {0.001f, 0.18f, 100.0f}) {
    ImageRgbF film{4, 2, std::vector<float>(24, bg)};
    DisplaySettings s;
    s.odt = OdtId::rec2020_pq_1000nit;
    const DisplayImage plain = apply_display_pipeline(film, color::color_space("srgb"), s);
    s.overlay = make_ui_overlay(overlay(4, 2, 255, 255), 150.0, 5.0);
    const DisplayImage ui = apply_display_pipeline(film, color::color_space("srgb"), s);
    // The overlay is stored as float AP1 and passes three 3×3 products: 1e-4 relative.
    for (float v : ui.nits) EXPECT_NEAR(v, 150.0, 150.0 * 1e-4) << bg;
    s.overlay = make_ui_overlay(overlay(4, 2, 255, 0), 150.0, 5.0);
    EXPECT_EQ(apply_display_pipeline(film, color::color_space("srgb"), s).code, plain.code);
  }
}

TEST(DisplayOverlay, RejectsBadOverlays) {
  EXPECT_THROW(make_ui_overlay(overlay(2, 2, 0, 0), 50.0, 5.0), UsageError);
  EXPECT_THROW(make_ui_overlay(overlay(2, 2, 0, 0), 200.0, 0.0), UsageError);
  EncodedImage rgb{2, 2, 3, 8, std::vector<std::uint16_t>(12, 0)};
  EXPECT_THROW(make_ui_overlay(rgb, 200.0, 5.0), UsageError);
  DisplaySettings s;
  s.overlay = make_ui_overlay(overlay(3, 3, 0, 0), 200.0, 5.0);
  EXPECT_THROW(apply_display_pipeline(ImageRgbF{2, 2, std::vector<float>(12, 0.f)}, color::color_space("srgb"), s),
               UsageError);
}

}  // namespace
}  // namespace prism::display
