// The decode of tagged PNG and JPEG textures (scene/image_color_tags.h) against Little
// CMS 2 on a grid of codes, not only the row the images hold: for each profile in
// data/color_tags, lcms2's relative-colorimetric transform of 16³ code triples into linear
// Rec.709 and ACEScg (profiles lcms2 builds itself, with its own Bradford adaptation)
// against Prism's curves and conversion matrix, before any clipping.
#include <gtest/gtest.h>
#include <lcms2.h>

#include <memory>
#include <string>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/io/read_to_end.h"
#include "prism/scene/image_color_tags.h"

namespace prism {
namespace {

const std::filesystem::path kData = std::filesystem::path(PRISM_SOURCE_DIR) / "tests/scene/loaders/data/color_tags";

struct CloseProfile {
  void operator()(void* p) const { cmsCloseProfile(p); }
};
struct DeleteTransform {
  void operator()(void* t) const { cmsDeleteTransform(t); }
};
using Profile = std::unique_ptr<void, CloseProfile>;

// A linear-light profile of `space`, built by lcms2 (cmsCreateRGBProfile adapts the
// colorants to D50 with its own Bradford).
Profile linear_profile(const color::ColorSpace& s) {
  const cmsCIExyY white{s.white.x, s.white.y, 1.0};
  const cmsCIExyYTRIPLE primaries{{s.red.x, s.red.y, 1.0}, {s.green.x, s.green.y, 1.0}, {s.blue.x, s.blue.y, 1.0}};
  cmsToneCurve* linear = cmsBuildGamma(nullptr, 1.0);
  cmsToneCurve* curves[3] = {linear, linear, linear};
  Profile p(cmsCreateRGBProfile(&white, &primaries, curves));
  cmsFreeToneCurve(linear);
  return p;
}

// Tolerance: both sides read the same s15Fixed16 colorants and tone tables; lcms2
// evaluates tabulated curves through its 16-bit interpolation (1/65535 steps) where Prism
// interpolates in double, and rounds its matrices in its own order: 1e-4 relative and 2e-5
// absolute cover both with room. A conversion that skips the connection space's D50
// adaptation is off by 25 % near blue (measured), far outside it.
void expect_agreement(const std::string& image, const std::string& profile_file, const char* target) {
  const ImageColorTags tags = read_png_color_tags(read_file_bytes(kData / image, "image"), image);
  ASSERT_FALSE(tags.srgb) << image;
  const color::ColorSpace& space = color::color_space(target);
  const Mat3 conversion = image_color_conversion(tags, space);
  const std::vector<unsigned char> bytes = read_file_bytes(kData / profile_file, "profile");
  const Profile in(cmsOpenProfileFromMem(bytes.data(), static_cast<cmsUInt32Number>(bytes.size())));
  ASSERT_TRUE(in);
  const Profile out = linear_profile(space);
  const std::unique_ptr<void, DeleteTransform> t(cmsCreateTransform(
      in.get(), TYPE_RGB_DBL, out.get(), TYPE_RGB_DBL, INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_NOOPTIMIZE | cmsFLAGS_NOCACHE));
  ASSERT_TRUE(t);
  int failures = 0;
  for (unsigned r = 0; r < 256; r += 17)
    for (unsigned g = 0; g < 256; g += 17)
      for (unsigned b = 0; b < 256; b += 17) {
        double code[3] = {r / 255.0, g / 255.0, b / 255.0}, lcms[3];
        cmsDoTransform(t.get(), code, lcms, 1);
        const Vec3d ours = conversion * Vec3d(decode_tagged_code(tags, 0, r, 255), decode_tagged_code(tags, 1, g, 255),
                                              decode_tagged_code(tags, 2, b, 255));
        for (int k = 0; k < 3; ++k)
          if (std::abs(ours[k] - lcms[k]) > 1e-4 * std::abs(lcms[k]) + 2e-5 && ++failures <= 5)
            ADD_FAILURE() << image << " to " << target << " at " << r << "," << g << "," << b << " channel " << k
                          << ": lcms2 " << lcms[k] << ", Prism " << ours[k];
      }
  EXPECT_EQ(failures, 0) << image << " to " << target;
}

TEST(ImageColorTagsLcms, IccProfilesAgreeOnEveryCode) {
  for (const char* target : {"srgb", "acescg", "rec2020"}) {
    expect_agreement("display-p3-icc.png", "display-p3-table-v2.icc", target);
    expect_agreement("rec2020-gamma22-icc.png", "rec2020-gamma22-v4.icc", target);
  }
}

}  // namespace
}  // namespace prism
