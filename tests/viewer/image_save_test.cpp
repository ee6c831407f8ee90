// The viewer's Save actions (image_save.h), on the frames the display and render workers
// hand the UI: the film EXR keeps the film's values, space and spp; the display image is
// saved with the colour metadata of its output transform (sRGB chunk for SDR sRGB, cICP +
// mDCv + cLLi for PQ, cICP in AVIF); debug views and float encodings are refused clearly.
#include "prism/viewer/image_save.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/io/avif.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"

namespace prism::viewer {
namespace {

class ImageSave : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("prism-image-save-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

// A 4×2 film with a ramp of grey and one saturated pixel, in ACEScg.
FilmFrame acescg_film() {
  FilmFrame f;
  f.film.width = 4;
  f.film.height = 2;
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) f.film.rgb.push_back(0.05f * static_cast<float>(i + 1));
  f.film.rgb[3 * 5 + 0] = 4.0f;  // a bright red
  f.film_space = color::color_space("acescg");
  f.spp = 37;
  f.elapsed_seconds = 1.5;
  return f;
}

DisplayFrame shown(const FilmFrame& film, const DisplayControls& controls) {
  DisplayFrame d;
  d.width = film.film.width;
  d.height = film.film.height;
  d.rgba.assign(static_cast<std::size_t>(d.width) * d.height * 4, 128);
  d.image = std::make_shared<display::DisplayImage>(
      display::apply_display_pipeline(film.film, film.film_space, resolved_display_settings(controls)));
  return d;
}

// The chunk types of a PNG, in file order, parsed from the file structure (ISO/IEC 15948:
// 8-byte signature, then length, type, data, CRC per chunk), independently of our writer.
std::vector<std::string> png_chunk_types(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> types;
  char header[8];
  in.read(header, 8);
  unsigned char len_type[8];
  while (in.read(reinterpret_cast<char*>(len_type), 8)) {
    const std::uint32_t length = (std::uint32_t(len_type[0]) << 24) | (std::uint32_t(len_type[1]) << 16) |
                                 (std::uint32_t(len_type[2]) << 8) | len_type[3];
    types.emplace_back(reinterpret_cast<const char*>(len_type + 4), 4);
    in.seekg(length + 4, std::ios::cur);
  }
  return types;
}

TEST_F(ImageSave, FilmExrKeepsValuesSpaceAndSampleCount) {
  const FilmFrame film = acescg_film();
  const auto path = dir_ / "film.exr";
  save_film_exr(path, film, "cornell-box");
  const ExrFile back = read_exr(path);
  ASSERT_EQ(back.image.rgb.size(), film.film.rgb.size());
  for (std::size_t i = 0; i < film.film.rgb.size(); ++i) EXPECT_EQ(back.image.rgb[i], film.film.rgb[i]) << i;
  ASSERT_TRUE(back.has_chromaticities);
  // AP1 red primary (ACES S-2014-004): x 0.713, y 0.293.
  EXPECT_FLOAT_EQ(back.chromaticities.red_x, 0.713f);
  EXPECT_FLOAT_EQ(back.chromaticities.red_y, 0.293f);
  EXPECT_EQ(back.metadata.ints.at("prism:spp"), 37);
  EXPECT_EQ(back.metadata.strings.at("prism:scene"), "cornell-box");
  EXPECT_THROW(save_film_exr(dir_ / "film.png", film, "x"), UsageError);
}

TEST_F(ImageSave, SdrPngCarriesTheSrgbChunk) {
  const FilmFrame film = acescg_film();
  DisplayControls controls;
  controls.auto_exposure = false;
  controls.ev100 = 0.0;
  const auto path = dir_ / "sdr.png";
  save_display_image(path, shown(film, controls), controls);
  const PngFile png = read_png(path);
  EXPECT_EQ(png.image.width, 4);
  EXPECT_EQ(png.image.bit_depth, 16);
  EXPECT_TRUE(png.has_srgb_chunk);
  const auto types = png_chunk_types(path);
  EXPECT_EQ(std::set<std::string>(types.begin(), types.end()).count("cICP"), 0u);
  // The ramp is increasing in the saved image (a real pipeline output, not the RGBA preview).
  EXPECT_LT(png.image.samples[0], png.image.samples[3 * 7]);
}

TEST_F(ImageSave, P3SdrPngCarriesAnIccProfileAndCicp) {
  const FilmFrame film = acescg_film();
  DisplayControls controls;
  controls.settings.odt = display::OdtId::p3d65_100nit;
  const auto path = dir_ / "p3.png";
  save_display_image(path, shown(film, controls), controls);
  const auto types = png_chunk_types(path);
  const std::set<std::string> set(types.begin(), types.end());
  EXPECT_EQ(set.count("iCCP"), 1u);
  EXPECT_EQ(set.count("cICP"), 1u);
  EXPECT_EQ(set.count("sRGB"), 0u);
  EXPECT_FALSE(read_png(path).has_srgb_chunk);
}

TEST_F(ImageSave, PqPngCarriesCicpAndHdr10Metadata) {
  const FilmFrame film = acescg_film();
  DisplayControls controls;
  controls.settings.odt = display::OdtId::rec2020_pq_1000nit;
  const auto path = dir_ / "hdr.png";
  save_display_image(path, shown(film, controls), controls);
  const auto types = png_chunk_types(path);
  const std::set<std::string> set(types.begin(), types.end());
  EXPECT_EQ(set.count("cICP"), 1u);
  EXPECT_EQ(set.count("mDCv"), 1u);
  EXPECT_EQ(set.count("cLLi"), 1u);
  EXPECT_EQ(set.count("sRGB"), 0u);
  // PNG requires the colour chunks before the image data.
  const auto position = [&](const std::string& t) { return std::find(types.begin(), types.end(), t) - types.begin(); };
  EXPECT_LT(position("cICP"), position("IDAT"));
}

TEST_F(ImageSave, AvifCarriesTheOutputCicp) {
  const FilmFrame film = acescg_film();
  DisplayControls controls;
  controls.settings.odt = display::OdtId::rec2020_pq_1000nit;
  const auto path = dir_ / "hdr.avif";
  save_display_image(path, shown(film, controls), controls);
  const AvifInfo info = read_avif_info(path);
  EXPECT_EQ(info.width, 4);
  EXPECT_EQ(info.bit_depth, 10);
  EXPECT_EQ(info.cicp.color_primaries, 9);            // BT.2020
  EXPECT_EQ(info.cicp.transfer_characteristics, 16);  // PQ
}

TEST_F(ImageSave, DebugViewsAndFloatEncodingsAreRefusedClearly) {
  const FilmFrame film = acescg_film();
  DisplayControls controls;
  controls.view = display::DebugView::gamut_clip;
  const DisplayFrame frame = shown(film, controls);
  EXPECT_THROW(save_display_image(dir_ / "view.avif", frame, controls), UsageError);
  save_display_image(dir_ / "view.png", frame, controls);  // saved as shown, 8-bit
  EXPECT_EQ(read_png(dir_ / "view.png").image.bit_depth, 8);
  EXPECT_THROW(save_display_image(dir_ / "image.jpg", frame, controls), UsageError);

  DisplayControls scrgb;
  scrgb.settings.encoding = display::DisplayEncoding::scrgb;
  EXPECT_THROW(save_display_image(dir_ / "scrgb.png", shown(film, scrgb), scrgb), UsageError);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "scrgb.png"));
}

}  // namespace
}  // namespace prism::viewer
