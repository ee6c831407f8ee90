// Prism's Radiance picture reader (io/radiance_hdr_reader.h) against stb_image's, the reader it
// replaced: the same texels for every file stb_image reads (the oracle: its floats are
// mantissa · 2^(e − 136) of the same RGBE bytes), and a one-line error, not a hang, where
// stb_image loops forever (a run-length scanline cut short).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

#include "prism/core/error.h"
#include "prism/core/memory_budget.h"
#include "prism/io/radiance_hdr_reader.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

using test::error_of;

std::span<const unsigned char> as_bytes(const std::string& s) {
  return {reinterpret_cast<const unsigned char*>(s.data()), s.size()};
}

// A .hdr written by stb_image_write (run-length encoded for widths 8 to 32767): flat
// regions (long runs), a bright disc and a ramp (dumps), black, and values whose exponents
// span the format's range.
std::string stb_written_hdr(int width, int height) {
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
      const float dx = static_cast<float>(x - width / 2), dy = static_cast<float>(y - height / 2);
      const bool disc = dx * dx + dy * dy < 16.0f;
      p[0] = y < height / 3 ? 0.5f : disc ? 5e4f : static_cast<float>(x) / width;
      p[1] = y < height / 3 ? 0.5f : std::ldexp(1.0f, (x * 7 + y) % 60 - 30);
      p[2] = (x + y) % 5 == 0 ? 0.0f : 0.25f * static_cast<float>(y + 1);
    }
  std::string out;
  stbi_write_hdr_to_func([](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  }, &out, width, height, 3, rgb.data());
  return out;
}

// Our texels, decoded, equal stb_image's floats, bitwise, sample by sample.
void expect_same_as_stb(const std::string& file) {
  int w = 0, h = 0, c = 0;
  float* stb = stbi_loadf_from_memory(as_bytes(file).data(), static_cast<int>(file.size()), &w, &h, &c, 3);
  ASSERT_NE(stb, nullptr) << stbi_failure_reason();
  const RadianceHeader header = read_radiance_header(as_bytes(file), "test.hdr");
  ASSERT_EQ(header.width, w);
  ASSERT_EQ(header.height, h);
  const std::vector<std::uint8_t> rgbe = read_radiance_texels(as_bytes(file), header, "test.hdr");
  ASSERT_EQ(rgbe.size(), static_cast<std::size_t>(w) * h * 4);
  std::size_t mismatches = 0;
  for (std::size_t t = 0; t < static_cast<std::size_t>(w) * h; ++t)
    for (std::size_t k = 0; k < 3; ++k)
      mismatches += rgbe_value(rgbe[4 * t + k], rgbe[4 * t + 3]) != stb[3 * t + k];
  stbi_image_free(stb);
  EXPECT_EQ(mismatches, 0u);
}

TEST(RadianceHdr, RunLengthEncodedFilesReadAsStbImageReadsThem) {
  for (const auto& [w, h] : {std::pair{8, 3}, {37, 11}, {300, 7}, {5, 4}}) {  // 5: too narrow for runs, flat
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    expect_same_as_stb(stb_written_hdr(w, h));
  }
}

// A file wide enough for runs whose scanline does not start 2, 2: stb_image reads the
// rest of the file as flat texels from the image's first one (rows already decoded are
// overwritten), and so does Prism.
TEST(RadianceHdr, AScanlineWithoutTheRunMarkerMakesTheRestFlat) {
  std::string flat = "#?RADIANCE\n# a comment\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1\n\n-Y 2 +X 9\n";
  for (int t = 0; t < 18; ++t) flat += std::string{static_cast<char>(100 + t), 7, static_cast<char>(t), static_cast<char>(120 + t % 3)};
  expect_same_as_stb(flat);
  // A run-length first row (each component one dump of 9 bytes), then a second row that
  // starts without the marker: its bytes and the 17 texels after it are the whole image.
  std::string two_rows = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 9\n";
  two_rows += std::string{2, 2, 0, 9};
  for (int k = 0; k < 4; ++k) {
    two_rows += static_cast<char>(9);
    for (int x = 0; x < 9; ++x) two_rows += static_cast<char>(k == 3 ? 128 + x : 10 * x + k);
  }
  for (int t = 0; t < 18; ++t) two_rows += std::string{1, 2, static_cast<char>(t), static_cast<char>(129 + t % 4)};
  expect_same_as_stb(two_rows);
}

// Every prefix of a run-length file is refused as truncated (stb_image spins forever on
// some: a zero-length dump read past the end never advances).
TEST(RadianceHdr, EveryTruncationIsAnErrorNotAHang) {
  const std::string file = stb_written_hdr(37, 5);
  const RadianceHeader header = read_radiance_header(as_bytes(file), "t.hdr");
  for (std::size_t n = header.data_offset; n < file.size(); ++n) {
    const std::string cut = file.substr(0, n);
    const std::string message = error_of<IoError>([&] { read_radiance_texels(as_bytes(cut), header, "t.hdr"); });
    ASSERT_NE(message.find("truncated"), std::string::npos) << n << ": " << message;
  }
}

TEST(RadianceHdr, CorruptFilesAreOneLineErrors) {
  const std::string rle = stb_written_hdr(8, 1);
  const RadianceHeader header = read_radiance_header(as_bytes(rle), "c.hdr");
  const auto texel_error = [&](std::string file) {
    return error_of<IoError>([&] { read_radiance_texels(as_bytes(file), header, "c.hdr"); });
  };
  std::string wrong_length = rle;
  wrong_length[header.data_offset + 3] = 9;  // a scanline of 9 texels in an image 8 wide
  EXPECT_NE(texel_error(wrong_length).find("scanline of 9 texels"), std::string::npos);
  std::string long_run = rle.substr(0, header.data_offset + 4);
  long_run += std::string{static_cast<char>(128 + 9), 1};  // a run of 9 in a scanline of 8
  long_run += std::string(16, '\0');                         // (and bytes enough for a whole image)
  EXPECT_NE(texel_error(long_run).find("run past the end"), std::string::npos);
  const auto header_error = [](const std::string& file) {
    return error_of<IoError>([&] { read_radiance_header(as_bytes(file), "h.hdr"); });
  };
  EXPECT_NE(header_error("#?RADIANCE\n\n-Y 1 +X 1\n").find("FORMAT=32-bit_rle_rgbe"), std::string::npos);
  for (const char* line : {"-Y 1 -Y 1", "Y 1 X 1", "-Y 1", "-Z 1 +X 1", "-Y 1 +X"})
    EXPECT_NE(header_error(std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n") + line + "\n").find("resolution line"),
              std::string::npos)
        << line;
  EXPECT_NE(header_error("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n").find("no end"), std::string::npos);
  EXPECT_NE(header_error("P6\n").find("not a Radiance picture"), std::string::npos);
}

// Through read_texture_file: RGBE kept (4 bytes per texel), the budget charged that and no
// decoder buffer, and the size checks of every image format.
TEST(RadianceHdr, TexturesKeepTheirRgbeTexelsAndTheBudgetCountsThem) {
  test::ScratchFolder dir;
  dir.write("sky.hdr", stb_written_hdr(64, 16));
  MemoryBudget budget(0);
  const TextureImage t = read_texture_file(dir / "sky.hdr", TextureEncoding::srgb, {32768, &budget});
  EXPECT_TRUE(t.has_rgbe());
  EXPECT_EQ(t.width, 64);
  EXPECT_EQ(t.channels, 3);
  EXPECT_EQ(budget.used_bytes(), 64u * 16u * 4u);
  EXPECT_EQ(texture_memory_need(as_bytes(test::read_bytes(dir / "sky.hdr")))->texel_bytes, 64u * 16u * 4u);
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "sky.hdr", TextureEncoding::srgb, 32); }).find("exceeds"),
            std::string::npos);
  // A 50-byte file claiming 30000² texels (3.4 GiB) is refused before they are allocated.
  dir.write("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 30000 +X 30000\n" + std::string(8, '\2'));
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "huge.hdr", TextureEncoding::srgb, 32768); })
                .find("at least"),
            std::string::npos);
  dir.write("empty.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 4\n");
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "empty.hdr", TextureEncoding::srgb, 32768); })
                .find("invalid size"),
            std::string::npos);
}

// The header variables that say what the texels mean (radiance_hdr.h): EXPOSURE and
// COLORCORR multiply up line by line, PRIMARIES is eight chromaticities, XYZE is a format.
TEST(RadianceHdr, HeaderVariablesAreRead) {
  const RadianceHeader plain = read_radiance_header(as_bytes(stb_written_hdr(8, 2)), "p.hdr");
  EXPECT_FALSE(plain.xyz);
  EXPECT_EQ(plain.exposure, 1.0);
  EXPECT_EQ(plain.color_correction, (std::array<double, 3>{1.0, 1.0, 1.0}));
  EXPECT_FALSE(plain.primaries);
  const RadianceHeader h = read_radiance_header(
      as_bytes("#?RADIANCE\nEXPOSURE=2\n\tpfilt -1 -e 2\nEXPOSURE= 1.5e+00\nCOLORCORR= 1 2 0.5\nCOLORCORR=2 2 2\n"
               "PRIMARIES= 0.708 0.292 0.170 0.797 0.131 0.046 0.3127 0.3290\nFORMAT=32-bit_rle_xyze \r\n\n-Y 1 +X 1\n"),
      "h.hdr");
  EXPECT_TRUE(h.xyz);
  EXPECT_EQ(h.exposure, 3.0);
  EXPECT_EQ(h.color_correction, (std::array<double, 3>{2.0, 4.0, 1.0}));
  ASSERT_TRUE(h.primaries);
  EXPECT_EQ(h.primaries->red.x, 0.708);
  EXPECT_EQ(h.primaries->green.y, 0.797);
  EXPECT_EQ(h.primaries->blue.x, 0.131);
  EXPECT_EQ(h.primaries->white.y, 0.3290);
  // Photoshop's line (Poly Haven's HDRIs carry it) names no primaries: the file is Rec.709.
  EXPECT_FALSE(read_radiance_header(as_bytes("#?RADIANCE\n# Made with Adobe Photoshop\nGAMMA=1\n"
                                             "PRIMARIES=0 0 0 0 0 0 0 0\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n"),
                                    "ps.hdr")
                   .primaries);
}

// A variable whose value does not read is a one-line error naming the file, the line and
// what was expected, not a texture silently read some other way.
TEST(RadianceHdr, UnreadableHeaderVariablesAreOneLineErrorsWithTheirLine) {
  const auto header_error = [](const std::string& lines) {
    return error_of<IoError>(
        [&] { read_radiance_header(as_bytes("#?RADIANCE\nSOFTWARE=test\n" + lines + "\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n"), "v.hdr"); });
  };
  const std::pair<const char*, const char*> cases[] = {
      {"EXPOSURE=abc", "is no exposure"},
      {"EXPOSURE=0", "is no exposure"},
      {"EXPOSURE=-2", "is no exposure"},
      {"EXPOSURE=2 3", "is no exposure"},
      {"EXPOSURE=inf", "is no exposure"},
      {"COLORCORR=1 1", "is no colour correction"},
      {"COLORCORR=1 0 1", "is no colour correction"},
      {"PRIMARIES=0.64 0.33 0.3 0.6 0.15 0.06 0.3127", "is no primaries"},
      {"PRIMARIES=0.64 0.33 0.3 0.6x 0.15 0.06 0.3127 0.329", "is no primaries"},
      {"PRIMARIES=0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329 1", "is no primaries"},
      {"PRIMARIES=0.6 0.3 0.4 0.2 0.2 0.1 0.3127 0.329", "names no RGB space"},  // collinear
      {"PRIMARIES=0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0", "names no RGB space"},  // white y = 0
  };
  for (const auto& [line, why] : cases) {
    const std::string message = header_error(line);
    EXPECT_NE(message.find("cannot read image 'v.hdr': header line 3 '" + std::string(line) + "' " + why),
              std::string::npos)
        << line << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(error_of<IoError>([] {
              read_radiance_header(as_bytes("#?RADIANCE\nFORMAT=32-bit_rle_cmyk\n\n-Y 1 +X 1\n"), "f.hdr");
            }).find("FORMAT=32-bit_rle_xyze expected"),
            std::string::npos);
}

// Radiance's eight pixel orders ("-Y H +X W" the standard; "+Y" from the bottom, "-X" from
// the right, "±X W ±Y H" scanlines as columns) all read as the same picture, rows top to
// bottom: each file below holds the standard file's texels in its own order.
TEST(RadianceHdr, EveryPixelOrderReadsAsTheSamePicture) {
  for (const auto& size : {std::pair{5, 3}, std::pair{12, 9}}) {  // flat; run-length-sized scanlines
    const int w = size.first, h = size.second;  // (clang 14 cannot capture a structured binding)
    const std::string standard = stb_written_hdr(w, h);
    const RadianceHeader sh = read_radiance_header(as_bytes(standard), "s.hdr");
    const std::vector<std::uint8_t> picture = read_radiance_texels(as_bytes(standard), sh, "s.hdr");
    const auto texel = [&](int x, int y) { return std::string(reinterpret_cast<const char*>(&picture[4 * (y * w + x)]), 4); };
    for (const bool columns : {false, true})
      for (const bool bottom_up : {false, true})
        for (const bool right_to_left : {false, true}) {
          const std::string y_axis = std::string(bottom_up ? "+Y " : "-Y ") + std::to_string(h);
          const std::string x_axis = std::string(right_to_left ? "-X " : "+X ") + std::to_string(w);
          const std::string resolution = columns ? x_axis + " " + y_axis : y_axis + " " + x_axis;
          SCOPED_TRACE(resolution + " " + std::to_string(w) + "x" + std::to_string(h));
          // Flat texels in the file's order (the first texel's r and g are not 2, 2, so a
          // reader takes them flat whatever the scanline length).
          std::string file = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" + resolution + "\n";
          const int scanlines = columns ? w : h, length = columns ? h : w;
          for (int s = 0; s < scanlines; ++s)
            for (int a = 0; a < length; ++a) {
              int x = columns ? s : a, y = columns ? a : s;
              if (right_to_left) x = w - 1 - x;
              if (bottom_up) y = h - 1 - y;
              file += texel(x, y);
            }
          const RadianceHeader header = read_radiance_header(as_bytes(file), "o.hdr");
          EXPECT_EQ(header.width, w);
          EXPECT_EQ(header.height, h);
          EXPECT_EQ(read_radiance_texels(as_bytes(file), header, "o.hdr"), picture);
        }
  }
}

}  // namespace
}  // namespace prism
