// SDR previews of HDR display light (display/sdr_preview.h): the extended Reinhard
// compression's fixed points (black stays black, the HDR peak lands exactly on SDR white, SDR
// white lands on (1 + 1/Lw²)/2 of it) and chromaticity kept below the clip.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/color/chromatic_adaptation.h"
#include "prism/display/sdr_preview.h"

namespace prism::display {
namespace {

DisplayImage hdr_pixels(const std::vector<Vec3d>& nits_2020) {
  DisplayImage img;
  img.width = static_cast<int>(nits_2020.size());
  img.height = 1;
  img.encoding = DisplayEncoding::pq;
  img.primaries = "rec2020";
  img.white_nits = 1000.0;
  for (const Vec3d& v : nits_2020)
    for (int c = 0; c < 3; ++c) {
      img.nits.push_back(static_cast<float>(v[c]));
      img.code.push_back(static_cast<float>(encode_display_nits(DisplayEncoding::pq, v[c], 1000.0)));
    }
  return img;
}

TEST(SdrPreview, ReinhardFixedPointsAndHue) {
  const double white = 200.0, lw = 1000.0 / white;
  // A D65 grey is equal in every RGB space with a D65 white.
  const DisplayImage hdr = hdr_pixels({{0, 0, 0}, {1000, 1000, 1000}, {white, white, white}, {40, 20, 10}});
  const DisplayImage sdr = sdr_preview_of_display_light(hdr, white);
  EXPECT_EQ(sdr.encoding, DisplayEncoding::srgb);
  EXPECT_EQ(sdr.primaries, "srgb");
  EXPECT_EQ(sdr.nits[0], 0.0f);
  // Peak → SDR white (100 nit, code 1), within float rounding of the 3×3 and its sum.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sdr.code[3 + c], 1.0, 1e-5);
  // SDR white → Y' = (1 + 1/Lw²)/2 of 100 nit.
  EXPECT_NEAR(sdr.nits[7], 100.0 * (1.0 + 1.0 / (lw * lw)) / 2.0, 1e-3);
  // A dim colour keeps its Rec.709 chromaticity (RGB scaled by one factor).
  const Mat3 to709 = color::conversion_matrix(color::color_space("rec2020"), color::color_space("srgb"));
  const Vec3d rel = to709 * Vec3d{40, 20, 10};
  EXPECT_NEAR(sdr.nits[9] / sdr.nits[10], rel.x / rel.y, 1e-4);
  EXPECT_NEAR(sdr.nits[11] / sdr.nits[10], rel.z / rel.y, 1e-4);
}

TEST(SdrPreview, TransferMarksCopiesOnlyChangedPixels) {
  const DisplayImage a = hdr_pixels({{1, 1, 1}, {2, 2, 2}, {3, 3, 3}});
  DisplayImage b = a;
  b.code[3] = 0.5f;  // pixel 1 marked
  const DisplayImage preview = sdr_preview_of_display_light(a, 100.0);
  const DisplayImage out = transfer_marks(a, b, preview);
  EXPECT_EQ(out.code[0], preview.code[0]);
  EXPECT_EQ(out.code[6], preview.code[6]);
  // Rec.709 cyan at 100 nit in an sRGB image: codes (0, 1, 1).
  EXPECT_NEAR(out.code[3], 0.0, 1e-6);
  EXPECT_NEAR(out.code[4], 1.0, 1e-6);
  EXPECT_NEAR(out.code[5], 1.0, 1e-6);
}

}  // namespace
}  // namespace prism::display
