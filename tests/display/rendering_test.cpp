// The rendering table (display/rendering.h): names, which targets each rendering has, the
// default encodings, and the pipeline's refusals for settings a rendering cannot honour.
#include <gtest/gtest.h>

#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/display/display_pipeline.h"
#include "prism/display/rendering.h"

namespace prism::display {
namespace {

TEST(Rendering, NamesRoundTrip) {
  for (const std::string& name : rendering_names()) EXPECT_EQ(rendering_name(parse_rendering(name)), name);
  EXPECT_EQ(parse_rendering("PBR_Neutral"), Rendering::pbr_neutral);
  EXPECT_EQ(parse_rendering("AgX"), Rendering::agx);
}

TEST(Rendering, UnknownNameListsTheValidOnes) {
  try {
    parse_rendering("filmic");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("agx"), std::string::npos) << e.what();
  }
}

TEST(Rendering, SdrRenderingsHaveSdrTargetsOnly) {
  for (Rendering r : {Rendering::agx, Rendering::pbr_neutral}) {
    EXPECT_EQ(rendering_target_names(r),
              (std::vector<std::string>{"srgb-100nit", "rec709-100nit", "p3d65-100nit", "rec2020-100nit"}));
    EXPECT_THROW(require_rendering_target(r, OdtId::rec2020_pq_1000nit), UsageError);
    EXPECT_THROW(require_rendering_target(r, OdtId::none), UsageError);
  }
  EXPECT_EQ(rendering_target_names(Rendering::aces1), odt_names());
}

TEST(Rendering, DefaultEncodings) {
  EXPECT_EQ(default_encoding(Rendering::aces1, OdtId::srgb_100nit), DisplayEncoding::srgb);
  EXPECT_EQ(default_encoding(Rendering::aces1, OdtId::rec2020_pq_1000nit), DisplayEncoding::pq);
  // The AgX configuration's sRGB and Display P3 displays have a 2.2 EOTF.
  EXPECT_EQ(default_encoding(Rendering::agx, OdtId::srgb_100nit), DisplayEncoding::gamma22);
  EXPECT_EQ(default_encoding(Rendering::agx, OdtId::p3d65_100nit), DisplayEncoding::gamma22);
  EXPECT_EQ(default_encoding(Rendering::agx, OdtId::rec709_100nit), DisplayEncoding::bt1886);
  EXPECT_EQ(default_encoding(Rendering::pbr_neutral, OdtId::srgb_100nit), DisplayEncoding::srgb);
}

TEST(Rendering, PipelineRefusesWhatOnlyAces1Has) {
  const ImageRgbF film{1, 1, {0.2f, 0.2f, 0.2f}};
  DisplaySettings s;
  s.rendering = Rendering::agx;
  s.blue_correction = 0.5;
  EXPECT_THROW(apply_display_pipeline(film, color::color_space("srgb"), s), UsageError);
  s.blue_correction = 0.0;
  s.odt = OdtId::rec2020_pq_1000nit;
  EXPECT_THROW(apply_display_pipeline(film, color::color_space("srgb"), s), UsageError);
}

// scRGB output of a rendering is the same light as its own encoding shows, in Rec.709.
TEST(Rendering, ScrgbIsTheSameDisplayLight) {
  const ImageRgbF film{2, 1, {0.2f, 0.5f, 0.05f, 3.0f, 0.1f, 0.4f}};
  for (Rendering r : {Rendering::agx, Rendering::pbr_neutral}) {
    DisplaySettings s;
    s.rendering = r;
    s.odt = OdtId::p3d65_100nit;
    const DisplayImage p3 = apply_display_pipeline(film, color::color_space("srgb"), s);
    s.encoding = DisplayEncoding::scrgb;
    const DisplayImage sc = apply_display_pipeline(film, color::color_space("srgb"), s);
    EXPECT_EQ(sc.primaries, "srgb");
    const Mat3 p3_to_709 = color::conversion_matrix(color::color_space(p3.primaries), color::color_space("srgb"));
    for (int i = 0; i < 2; ++i) {
      const Vec3d light = p3_to_709 * Vec3d{p3.nits[3 * i], p3.nits[3 * i + 1], p3.nits[3 * i + 2]};
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(sc.code[3 * i + k] * 80.0, light[k], 1e-3);  // float32 light
    }
  }
}

}  // namespace
}  // namespace prism::display
