// The colour-picker spaces (scene/color_picker_space.h, scene/emission.h): conversions
// between them, and which one holds a file's primaries (pbrt-v4 image textures keep their
// own colour space, TextureContent::color_own_gamut).
#include <gtest/gtest.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/scene/emission.h"

namespace prism {
namespace {

constexpr ColorPickerSpace kSpaces[] = {ColorPickerSpace::srgb, ColorPickerSpace::acescg, ColorPickerSpace::rec2020};

// Each conversion is the colour-space library's (cached), the identity within a space, and
// a conversion there and back is the identity to double round-off on O(1) entries (1e-12).
TEST(ColorPickerSpace, ConversionsAreTheLibrarysAndInvertEachOther) {
  for (const ColorPickerSpace from : kSpaces)
    for (const ColorPickerSpace to : kSpaces) {
      const Mat3& m = picker_space_conversion(from, to);
      const Mat3 expected = from == to ? Mat3::identity()
                                       : color::conversion_matrix(picker_color_space(from), picker_color_space(to));
      const Mat3 round_trip = picker_space_conversion(to, from) * m;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          EXPECT_EQ(m(i, j), expected(i, j)) << picker_space_name(from) << " → " << picker_space_name(to);
          EXPECT_NEAR(round_trip(i, j), i == j ? 1.0 : 0.0, 1e-12);
        }
    }
  EXPECT_STREQ(picker_space_label(ColorPickerSpace::srgb), "Rec.709");
  EXPECT_STREQ(picker_space_name(ColorPickerSpace::rec2020), "rec2020");
}

// Rec.709 holds itself; Adobe RGB lies within Rec.2020 but not Rec.709 (its green); the P3
// reds (Display P3, and DCI-P3 with its DCI white adapted) lie just outside Rec.2020
// (Rec.2020 blue −0.0012 and −0.0008: `prism color convert --from display-p3 --to rec2020
// 1 0 0`) and inside ACEScg; ACEScg's green lies outside Rec.2020, and ACES2065-1's
// imaginary primaries outside everything: all four go to ACEScg.
TEST(ColorPickerSpace, SmallestSpaceHoldingAFilesPrimaries) {
  const struct {
    const char* file;
    ColorPickerSpace expected;
  } cases[] = {{"srgb", ColorPickerSpace::srgb},        {"display-p3", ColorPickerSpace::acescg},
               {"dci-p3", ColorPickerSpace::acescg},   {"adobe-rgb", ColorPickerSpace::rec2020},
               {"rec2020", ColorPickerSpace::rec2020},  {"acescg", ColorPickerSpace::acescg},
               {"aces2065-1", ColorPickerSpace::acescg}};
  for (const auto& c : cases)
    EXPECT_EQ(smallest_picker_space_holding(color::color_space(c.file)), c.expected) << c.file;
}

}  // namespace
}  // namespace prism
