#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "support/exr_test_files.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {
namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
 protected:
  // Nothing but the named files may be left in the directory (no temporaries).
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  const test::ScratchFolder scratch_;
  const fs::path dir_ = scratch_.path();
};

ImageRgbF gradient(int w, int h) {
  ImageRgbF img{w, h, std::vector<float>(3u * w * h)};
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = static_cast<float>(i) * 0.37f - 3.0f;
  return img;
}

TEST_F(ImageIo, ExrRoundTripKeepsPixelsChromaticitiesAndMetadata) {
  const ImageRgbF img = gradient(7, 5);
  const ExrChromaticities c{0.64f, 0.33f, 0.3f, 0.6f, 0.15f, 0.06f, 0.3127f, 0.329f};
  ExrMetadata meta;
  meta.strings["prism:version"] = "1.2.3";
  meta.ints["prism:spp"] = 64;
  meta.doubles["prism:renderSeconds"] = 1.5;
  write_exr(dir_ / "a.exr", img, c, meta);
  const ExrFile f = read_exr(dir_ / "a.exr");
  EXPECT_EQ(f.image.width, 7);
  EXPECT_EQ(f.image.height, 5);
  EXPECT_EQ(f.image.rgb, img.rgb);  // 32-bit float storage is lossless
  ASSERT_TRUE(f.has_chromaticities);
  EXPECT_FLOAT_EQ(f.chromaticities.red_x, 0.64f);
  EXPECT_FLOAT_EQ(f.chromaticities.white_y, 0.329f);
  EXPECT_EQ(f.metadata.strings.at("prism:version"), "1.2.3");
  EXPECT_EQ(f.metadata.ints.at("prism:spp"), 64);
  EXPECT_DOUBLE_EQ(f.metadata.doubles.at("prism:renderSeconds"), 1.5);
  EXPECT_EQ(files(), std::vector<std::string>{"a.exr"});
}

TEST_F(ImageIo, PngRoundTrip8And16Bit) {
  for (int depth : {8, 16}) {
    EncodedImage img{5, 3, 3, depth, {}};
    for (int i = 0; i < 45; ++i) img.samples.push_back(static_cast<std::uint16_t>((i * 4099) % (depth == 8 ? 256 : 65536)));
    const fs::path path = dir_ / ("p" + std::to_string(depth) + ".png");
    write_png(path, img);
    const PngFile f = read_png(path);
    EXPECT_EQ(f.image.bit_depth, depth);
    EXPECT_EQ(f.image.channels, 3);
    EXPECT_EQ(f.image.samples, img.samples);
    EXPECT_TRUE(f.has_srgb_chunk);
  }
}

TEST_F(ImageIo, ReadingMissingOrCorruptFilesThrowsIoError) {
  EXPECT_THROW(read_exr(dir_ / "missing.exr"), IoError);
  EXPECT_THROW(read_png(dir_ / "missing.png"), IoError);
  { std::ofstream(dir_ / "junk.exr") << "this is not an EXR file at all"; }
  { std::ofstream(dir_ / "junk.png") << "\x89PNG\r\n\x1a\n truncated"; }
  EXPECT_THROW(read_exr(dir_ / "junk.exr"), IoError);
  EXPECT_THROW(read_png(dir_ / "junk.png"), IoError);
}

// A luminance-only file (Y alone) reads as grey, Y in R, G and B (it read as black); a file
// with none of R, G, B, Y is an error, not a black image.
TEST_F(ImageIo, LuminanceOnlyExrReadsAsGrey) {
  const std::vector<float> values = {0.0f, 0.5f, 1.0f, 2.0f, 0.25f, 8.0f};
  test::write_single_channel_exr(dir_ / "y.exr", "Y", Imf::HALF, values);
  const ExrFile f = read_exr(dir_ / "y.exr");
  ASSERT_EQ(f.image.rgb.size(), 18u);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(f.image.rgb[3 * i + c], values[i]) << i << " " << c;
  test::write_single_channel_exr(dir_ / "z.exr", "Z", Imf::FLOAT, values);
  EXPECT_THROW(read_exr(dir_ / "z.exr"), IoError);
}

TEST_F(ImageIo, TruncatedExrIsAnError) {
  write_exr(dir_ / "full.exr", gradient(64, 64), ExrChromaticities{0.64f, 0.33f, 0.3f, 0.6f, 0.15f, 0.06f, 0.3127f, 0.329f});
  std::ifstream in(dir_ / "full.exr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  { std::ofstream(dir_ / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2); }
  EXPECT_THROW(read_exr(dir_ / "cut.exr"), IoError);
}

TEST_F(ImageIo, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
  { std::ofstream(dir_ / "keep.png") << "old"; }
  EncodedImage bad{4, 4, 3, 8, std::vector<std::uint16_t>(5)};  // wrong sample count
  EXPECT_THROW(write_png(dir_ / "keep.png", bad), IoError);
  std::ifstream in(dir_ / "keep.png");
  std::string content;
  in >> content;
  EXPECT_EQ(content, "old");
  EXPECT_EQ(files(), std::vector<std::string>{"keep.png"});
}

TEST_F(ImageIo, AtomicFileRemovesUncommittedTemporary) {
  fs::path tmp;
  {
    AtomicFile f(dir_ / "x.bin");
    tmp = f.temporary_path();
    std::ofstream(tmp) << "partial";
    EXPECT_TRUE(fs::exists(tmp));
  }
  EXPECT_FALSE(fs::exists(tmp));
  EXPECT_FALSE(fs::exists(dir_ / "x.bin"));
}

TEST_F(ImageIo, WritabilityCheck) {
  EXPECT_NO_THROW(check_writable_output(dir_ / "ok.exr"));
  EXPECT_THROW(check_writable_output(dir_ / "no-such-dir" / "x.exr"), IoError);
  EXPECT_THROW(check_writable_output(dir_), IoError);  // a directory
}

}  // namespace
}  // namespace prism
