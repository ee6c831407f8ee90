// The OpenColorIO display path (display/ocio_display.h) with a tiny config written here:
// a linear Rec.709 scene_linear space and an sRGB display whose view applies the sRGB curve
// (OCIO's ExponentWithLinearTransform, γ 2.4, offset 0.055 — IEC 61966-2-1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"
#include "prism/display/ocio_display.h"
#include "support/scratch_folder.h"

namespace prism::display {
namespace {

constexpr const char* kConfig = R"(ocio_profile_version: 2
roles:
  default: linear
  scene_linear: linear
displays:
  sRGB:
    - !<View> {name: Standard, colorspace: srgb_display}
    - !<View> {name: Raw, colorspace: linear}
colorspaces:
  - !<ColorSpace>
    name: linear
    family: ""
    isdata: false
  - !<ColorSpace>
    name: srgb_display
    family: ""
    isdata: false
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
)";

std::filesystem::path write_config(const test::ScratchFolder& scratch) { return scratch.write("config.ocio", kConfig); }

ImageRgbF ramp() {
  ImageRgbF film{11, 1, {}};
  for (int i = 0; i <= 10; ++i)
    for (int c = 0; c < 3; ++c) film.rgb.push_back(static_cast<float>(0.1 * i * (c + 1) / 3.0));
  return film;
}

TEST(DisplayOcio, ConfigFileDisplayAndView) {
  const test::ScratchFolder scratch;
  const auto path = write_config(scratch);
  const ImageRgbF film = ramp();
  const DisplayImage out = apply_ocio_display(film, 1.0, {path.string(), "sRGB", "Standard", ""});
  ASSERT_EQ(out.code.size(), film.rgb.size());
  // OCIO evaluates the curve analytically in float: 1e-5 covers float32 rounding.
  for (std::size_t i = 0; i < film.rgb.size(); ++i) EXPECT_NEAR(out.code[i], color::srgb_encode(film.rgb[i]), 1e-5) << i;
  const DisplayImage raw = apply_ocio_display(film, 2.0, {path.string(), "sRGB", "Raw", ""});
  for (std::size_t i = 0; i < film.rgb.size(); ++i) EXPECT_NEAR(raw.code[i], 2.0 * film.rgb[i], 1e-6);
}

// The library takes the config as a parameter, never from $OCIO (the command line reads it):
// no path is an error even with $OCIO set; empty display/view names pick the defaults.
TEST(DisplayOcio, ConfigIsAParameterAndNamesDefault) {
  const test::ScratchFolder scratch;
  const auto path = write_config(scratch);
  const DisplayImage out = apply_ocio_display(ramp(), 1.0, {path.string(), "", "", ""});  // default display/view
  EXPECT_NEAR(out.code[3 * 5], color::srgb_encode(0.5 / 3.0), 1e-5);
  const OcioDisplayView chosen = resolve_ocio_display_view({path.string(), "", "", ""});
  EXPECT_EQ(chosen.display, "sRGB");
  EXPECT_EQ(chosen.view, "Standard");
  const char* old = std::getenv("OCIO");
  const std::string saved = old ? old : "";
  setenv("OCIO", path.c_str(), 1);
  EXPECT_THROW(apply_ocio_display(ramp(), 1.0, {"", "sRGB", "Standard", ""}), UsageError);
  if (old) setenv("OCIO", saved.c_str(), 1);
  else unsetenv("OCIO");
}

TEST(DisplayOcio, BadConfigDisplayOrView) {
  const test::ScratchFolder scratch;
  const auto path = write_config(scratch);
  EXPECT_THROW(apply_ocio_display(ramp(), 1.0, {path.string(), "P3", "Standard", ""}), UsageError);
  EXPECT_THROW(apply_ocio_display(ramp(), 1.0, {path.string(), "sRGB", "Filmic", ""}), UsageError);
  EXPECT_THROW(apply_ocio_display(ramp(), 1.0, {path.string(), "sRGB", "Standard", "nope"}), UsageError);
  EXPECT_THROW(apply_ocio_display(ramp(), 1.0, {"/nonexistent/config.ocio", "sRGB", "Standard", ""}), UsageError);
}

}  // namespace
}  // namespace prism::display
