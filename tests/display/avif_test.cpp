// AVIF output (io/avif.h), read back with libavif's own decoder: CICP, size, depth and
// (lossless identity-matrix coding) the samples themselves.
#include <gtest/gtest.h>

#include <filesystem>

#include "prism/core/error.h"
#include "prism/io/avif.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

EncodedImage gradient(int depth) {
  EncodedImage img{37, 11, 3, depth, {}};
  const int max_code = (1 << depth) - 1;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c)
        img.samples.push_back(static_cast<std::uint16_t>((x * 97 + y * 31 + c * 400) % (max_code + 1)));
  return img;
}

TEST(DisplayAvif, WritesCicpAndReadsBackLosslessly) {
  for (int depth : {10, 12}) {
    const test::ScratchFolder scratch;
    const auto path = scratch / ("gradient_" + std::to_string(depth) + ".avif");
    const EncodedImage img = gradient(depth);
    write_avif(path, img, CicpInfo{9, 16, 0, 1});
    const AvifInfo info = read_avif_info(path);
    EXPECT_EQ(info.width, 37);
    EXPECT_EQ(info.height, 11);
    EXPECT_EQ(info.bit_depth, depth);
    EXPECT_EQ(info.cicp.color_primaries, 9);
    EXPECT_EQ(info.cicp.transfer_characteristics, 16);
    EXPECT_EQ(info.cicp.matrix_coefficients, 0);
    EXPECT_EQ(info.cicp.video_full_range, 1);
    EXPECT_TRUE(info.yuv444);
    EXPECT_EQ(read_avif(path).samples, img.samples);
  }
}

TEST(DisplayAvif, RejectsBadInput) {
  const test::ScratchFolder scratch;
  const auto path = scratch / "bad.avif";
  EXPECT_THROW(write_avif(path, gradient(8), CicpInfo{}), UsageError);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_THROW(read_avif_info(scratch / "no_such_file.avif"), IoError);
}

}  // namespace
}  // namespace prism
