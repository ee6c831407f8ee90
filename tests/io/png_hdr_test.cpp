// HDR PNG metadata (PNG Third Edition cICP, mDCv, cLLi) read back by an independent reader:
// libpng's own unknown-chunk reading, not our writer's code. MaxCLL/MaxFALL are exact on a
// synthetic image.
#include <png.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "prism/color/icc_profile.h"
#include "prism/core/error.h"
#include "prism/io/hdr10_metadata.h"
#include "prism/io/png.h"
#include "prism/io/png_hdr.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

// What libpng itself reads back: every cICP/mDCv/cLLi chunk by name, and the iCCP
// chunk's name and (decompressed) profile.
struct PngColorChunks {
  std::map<std::string, std::vector<std::uint8_t>> unknown;
  std::string icc_name;
  std::vector<std::uint8_t> icc_profile;  // empty: no iCCP
};

// The setjmp frame holds the libpng calls only; the file is opened and closed by the caller.
bool read_color_chunks_from(std::FILE* fp, PngColorChunks& out) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, fp);
  static const png_byte kNames[] = "cICP\0mDCv\0cLLi";
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_ALWAYS, kNames, 3);
  png_read_info(png, info);
  png_unknown_chunkp chunks = nullptr;
  const int n = png_get_unknown_chunks(png, info, &chunks);
  for (int i = 0; i < n; ++i)
    out.unknown[std::string(reinterpret_cast<const char*>(chunks[i].name), 4)] =
        std::vector<std::uint8_t>(chunks[i].data, chunks[i].data + chunks[i].size);
  png_charp name = nullptr;
  int compression = 0;
  png_bytep data = nullptr;
  png_uint_32 length = 0;
  if (png_get_iCCP(png, info, &name, &compression, &data, &length) != 0) {
    out.icc_name = name;
    out.icc_profile.assign(data, data + length);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

PngColorChunks read_color_chunks(const std::filesystem::path& path) {
  PngColorChunks out;
  std::FILE* fp = std::fopen(path.c_str(), "rb");
  if (!fp) return out;
  if (!read_color_chunks_from(fp, out)) out = {};
  std::fclose(fp);
  return out;
}

std::map<std::string, std::vector<std::uint8_t>> read_unknown_chunks(const std::filesystem::path& path) {
  return read_color_chunks(path).unknown;
}

std::uint32_t be32(const std::vector<std::uint8_t>& d, std::size_t at) {
  return (std::uint32_t(d[at]) << 24) | (std::uint32_t(d[at + 1]) << 16) | (std::uint32_t(d[at + 2]) << 8) | d[at + 3];
}
std::uint32_t be16(const std::vector<std::uint8_t>& d, std::size_t at) { return (std::uint32_t(d[at]) << 8) | d[at + 1]; }

TEST(ContentLightLevel, ExactOnSyntheticImage) {
  // Per-pixel max(R,G,B): 100, 1000, 10, 2 (negatives count as 0) → MaxCLL 1000,
  // MaxFALL 1112 / 4 = 278.
  const std::vector<float> nits{100, 50, 0, 0, 0, 1000, 10, 10, 10, -5, 2, 1};
  const ContentLightLevel c = content_light_level(nits);
  EXPECT_EQ(c.max_cll_nits, 1000.0);
  EXPECT_EQ(c.max_fall_nits, 278.0);
  EXPECT_EQ(content_light_level({}).max_cll_nits, 0.0);
}

TEST(PngHdr, ChunksReadBackWithLibpng) {
  const test::ScratchFolder scratch;
  const auto path = scratch / "hdr.png";
  EncodedImage img;
  img.width = 2;
  img.height = 1;
  img.bit_depth = 16;
  img.samples = {0, 1000, 65535, 40000, 20000, 5};
  PngColorMetadata meta;
  meta.cicp = CicpInfo{9, 16, 0, 1};
  meta.mastering_display = MasteringDisplay{0.708, 0.292, 0.170, 0.797, 0.131, 0.046, 0.3127, 0.3290, 1000.0, 0.0001};
  meta.content_light_level = ContentLightLevel{1000.0, 278.0};
  write_png_with_color_metadata(path, img, meta);

  const auto chunks = read_unknown_chunks(path);
  ASSERT_EQ(chunks.count("cICP"), 1u);
  ASSERT_EQ(chunks.count("mDCv"), 1u);
  ASSERT_EQ(chunks.count("cLLi"), 1u);
  EXPECT_EQ(chunks.at("cICP"), (std::vector<std::uint8_t>{9, 16, 0, 1}));
  const auto& m = chunks.at("mDCv");
  ASSERT_EQ(m.size(), 24u);
  // Chromaticities in 0.00002 units, R, G, B, white: 0.708 → 35400 ... 0.3290 → 16450.
  const std::uint32_t xy[8] = {35400, 14600, 8500, 39850, 6550, 2300, 15635, 16450};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(be16(m, 2 * i), xy[i]) << i;
  EXPECT_EQ(be32(m, 16), 10000000u);  // 1000 cd/m² in 0.0001 units
  EXPECT_EQ(be32(m, 20), 1u);         // 0.0001 cd/m²
  const auto& l = chunks.at("cLLi");
  ASSERT_EQ(l.size(), 8u);
  EXPECT_EQ(be32(l, 0), 10000000u);
  EXPECT_EQ(be32(l, 4), 2780000u);

  // The pixels survive too (read by the ordinary reader).
  const PngFile back = read_png(path);
  EXPECT_EQ(back.image.bit_depth, 16);
  EXPECT_EQ(back.image.samples, img.samples);
  EXPECT_FALSE(back.has_srgb_chunk);
}

TEST(PngHdr, IccProfileReadsBackWithLibpng) {
  const test::ScratchFolder scratch;
  const auto path = scratch / "iccp.png";
  EncodedImage img{2, 1, 3, 8, {0, 128, 255, 10, 20, 30}};
  PngColorMetadata meta;
  meta.cicp = CicpInfo{12, 13, 0, 1};
  meta.icc_profile = color::make_icc_display_profile(color::color_space("display-p3"), color::IccToneCurve::srgb,
                                                     "Prism display-p3");
  meta.icc_profile_name = "Prism display-p3";
  write_png_with_color_metadata(path, img, meta);
  const PngColorChunks back = read_color_chunks(path);
  ASSERT_FALSE(back.icc_profile.empty());
  EXPECT_EQ(back.icc_name, "Prism display-p3");
  EXPECT_EQ(back.icc_profile, meta.icc_profile);
  EXPECT_EQ(read_png(path).has_srgb_chunk, false);
  EXPECT_EQ(back.unknown.count("cICP"), 1u);

  // PNG allows an sRGB chunk or an ICC profile, not both.
  meta.srgb_chunk = true;
  EXPECT_THROW(write_png_with_color_metadata(path, img, meta), IoError);
}

}  // namespace
}  // namespace prism
