// Debug views (display/debug_views.h, luminance_view.h, chromaticity_diagram.h, raster.h).
#include <gtest/gtest.h>

#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/core/error.h"
#include "prism/display/chromaticity_diagram.h"
#include "prism/display/debug_views.h"
#include "prism/display/luminance_view.h"
#include "prism/display/spectral_locus.h"

namespace prism::display {
namespace {

TEST(DisplayView, Names) {
  EXPECT_EQ(parse_debug_view("gamut-clip"), DebugView::gamut_clip);
  EXPECT_EQ(parse_debug_view("SDR_HDR_SPLIT"), DebugView::sdr_hdr_split);
  EXPECT_THROW(parse_debug_view("heatmap"), UsageError);
  EXPECT_EQ(debug_view_names().size(), 7u);
  EXPECT_EQ(parse_debug_view("bloom"), DebugView::bloom);
}

TEST(DisplayView, LuminanceScaleAndLabels) {
  const std::vector<float> y{0.02f, 0.5f, 3.0f, 450.0f};
  const LuminanceScale s = luminance_scale_for(y);
  EXPECT_EQ(s.min_decade, -2);
  EXPECT_EQ(s.max_decade, 3);
  EXPECT_EQ(decade_label(-3), "0.001");
  EXPECT_EQ(decade_label(0), "1");
  EXPECT_EQ(decade_label(4), "10000");
  EXPECT_EQ(decade_label(5), "1E5");
  // Each decade gets its own colour; below the scale black, above white.
  EXPECT_NE(false_colour(0.05, s).x + false_colour(0.05, s).y, false_colour(5.0, s).x + false_colour(5.0, s).y);
  EXPECT_EQ(false_colour(1e-4, s).x, 0.0);
  EXPECT_EQ(false_colour(1e4, s).y, 1.0);
  const Canvas c = luminance_false_colour_view(y, 2, 2, s);
  EXPECT_EQ(c.image.width, 2);
  EXPECT_GT(c.image.height, 2 + 10);  // the legend strip
}

TEST(DisplayView, GamutClipMarksOnlyOutOfRec709) {
  DisplayImage img;
  img.width = 2;
  img.height = 1;
  img.encoding = DisplayEncoding::pq;
  img.white_nits = 1000;
  img.primaries = "rec2020";
  img.nits = {50, 50, 50, 0, 80, 0};  // grey; Rec.2020 pure green (outside Rec.709)
  img.code.assign(6, 0.0f);
  EXPECT_EQ(mark_gamut_clip(img), 1u);
  EXPECT_EQ(img.nits[0], 50.0f);
  // The marked pixel is Rec.709 cyan at 100 nits: no red, equal green and blue in Rec.709.
  const Mat3 to709 = color::conversion_matrix(color::color_space("rec2020"), color::color_space("srgb"));
  const Vec3d c = to709 * Vec3d{img.nits[3], img.nits[4], img.nits[5]};
  EXPECT_NEAR(c.x, 0.0, 1e-3);
  EXPECT_NEAR(c.y, 100.0, 1e-3);
  EXPECT_NEAR(c.z, 100.0, 1e-3);
}

TEST(DisplayView, SdrHdrSplitShowsSdrWhiteOnTheLeft) {
  ImageRgbF film{8, 2, std::vector<float>(48, 1000.0f)};  // far above white: SDR clips to its white
  DisplaySettings s;
  s.odt = OdtId::rec2020_pq_1000nit;
  const DisplayImage split = sdr_hdr_split_view(film, color::color_space("srgb"), s, 200.0);
  EXPECT_NEAR(split.nits[0] + split.nits[1] + split.nits[2], 3 * 200.0, 0.5);  // left: SDR white at 200
  EXPECT_GT(split.nits[3 * 7 + 1], 500.0f);                                    // right: HDR highlight
  s.odt = OdtId::srgb_100nit;
  EXPECT_THROW(sdr_hdr_split_view(film, color::color_space("srgb"), s, 200.0), UsageError);
}

TEST(DisplayView, ChromaticityDiagramDrawsLocusAndPixels) {
  ImageRgbF film{1, 1, {0.0f, 1.0f, 0.0f}};  // Rec.709 green: xy (0.30, 0.60)
  const Canvas c = chromaticity_diagram(film, color::color_space("srgb"), color::color_space("display-p3"), 240);
  // The 520 nm point of the locus is drawn white.
  const auto& locus = spectral_locus_xy();
  const color::Chromaticity g520 = locus[520 - 380];
  const Vec3d p = chromaticity_to_canvas(g520.x, g520.y, 240);
  const float* px = &c.image.rgb[3 * (std::size_t(std::lround(p.y)) * c.image.width + std::size_t(std::lround(p.x)))];
  EXPECT_EQ(px[0] + px[1] + px[2], 3.0f);
  // The image's one pixel is plotted near (0.30, 0.60): not background there.
  const Vec3d q = chromaticity_to_canvas(0.30, 0.60, 240);
  bool found = false;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const float* v = &c.image.rgb[3 * (std::size_t(int(q.y) + dy) * c.image.width + std::size_t(int(q.x) + dx))];
      found |= v[0] > 0.3f && v[2] < v[0];
    }
  EXPECT_TRUE(found);
}

TEST(DisplayView, FontDrawsDigits) {
  Canvas c(16, 8, {0, 0, 0});
  EXPECT_EQ(c.draw_text(0, 0, "10", {1, 1, 1}, 1), 7);
  EXPECT_EQ(c.image.rgb[3 * 1], 1.0f);   // '1' top row middle
  EXPECT_EQ(c.image.rgb[3 * 0], 0.0f);
  EXPECT_EQ(text_width_px("NIT", 2), 22);
}

}  // namespace
}  // namespace prism::display
