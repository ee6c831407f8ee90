// Radiance picture output (io/radiance_hdr_writer.h): RGBE rounded to nearest, the header
// naming the texels' space, run-length scanlines that stb_image (an independent reader, the
// oracle) and Prism's own reader decode to the same texels, and XYZE for the spectral film.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <stb_image.h>

#include "prism/color/color_space.h"
#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/radiance_hdr_writer.h"
#include "prism/io/radiance_rle.h"
#include "prism/io/radiance_hdr_reader.h"
#include "prism/scene/texture.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

float decoded(unsigned char mantissa, unsigned char exponent) { return rgbe_value(mantissa, exponent); }

TEST(RadianceHdrWriter, EncodesToTheNearestRgbeValue) {
  // Exact values come back exactly: 0.5 = 128 · 2^(128 − 136).
  RgbeBytes b = encode_rgbe(0.5f, 0.25f, 0.125f);
  EXPECT_EQ(b.r, 128);
  EXPECT_EQ(b.g, 64);
  EXPECT_EQ(b.b, 32);
  EXPECT_EQ(b.e, 128);
  // 0.999 · 256 rounds to 256, which is the next exponent's 128: 1.0, not Ward's truncated
  // 255 · 2^-8 = 0.996.
  b = encode_rgbe(0.999f, 0.0f, 0.0f);
  EXPECT_EQ(decoded(b.r, b.e), 1.0f);
  // Negative and non-finite channels are 0; a pixel below the format's range is black.
  b = encode_rgbe(-1.0f, NAN, 2.0f);
  EXPECT_EQ(b.r, 0);
  EXPECT_EQ(b.g, 0);
  EXPECT_EQ(decoded(b.b, b.e), 2.0f);
  b = encode_rgbe(1e-39f, 0.0f, 0.0f);
  EXPECT_EQ(b.e, 0);
  // Beyond the largest exponent: the largest value, 255 · 2^119.
  b = encode_rgbe(3e38f, 1.0f, 0.0f);
  EXPECT_EQ(decoded(b.r, b.e), std::ldexp(255.0f, 119));
}

// Every channel lies within half a step of its value, the step being 2^(e − 8) for the
// exponent e the pixel is written with: the largest channel's (frexp's), or the next one
// where that channel rounds up to 256 (then 128 of the next): the format's resolution,
// rounded to nearest.
TEST(RadianceHdrWriter, EveryChannelIsWithinHalfAStepOfItsValue) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (int i = 0; i < 100000; ++i) {
    const float scale = std::ldexp(1.0f, exponent(rng));
    const float c[3] = {unit(rng) * scale, unit(rng) * scale, unit(rng) * scale};
    const RgbeBytes b = encode_rgbe(c[0], c[1], c[2]);
    int e = 0;
    std::frexp(std::max({c[0], c[1], c[2]}), &e);
    const int written = b.e - 128;
    ASSERT_TRUE(written == e || written == e + 1) << written << " for " << e;
    const double half_step = std::ldexp(1.0, written - 9);
    const unsigned char m[3] = {b.r, b.g, b.b};
    for (int k = 0; k < 3; ++k)
      ASSERT_LE(std::abs(static_cast<double>(decoded(m[k], b.e)) - c[k]), half_step * (1.0 + 1e-12))
          << c[0] << " " << c[1] << " " << c[2] << " channel " << k;
  }
}

ImageRgbF test_image(int width, int height) {
  ImageRgbF image{width, height, std::vector<float>(3u * width * height)};
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &image.rgb[3u * (y * width + x)];
      const bool flat = x < width / 2;  // long runs of one pixel, and noise (dumps)
      for (int k = 0; k < 3; ++k) p[k] = flat ? 0.25f * (k + 1) : unit(rng) * std::ldexp(1.0f, (x + y) % 20 - 10);
    }
  return image;
}

// Writes an ACEScg image and reads it back twice: stb_image decodes the file to the same
// floats as Prism's reader (so the run-length scanlines are well formed for a reader that is
// not ours), and Prism's reader keeps it in ACEScg, as its header says, texel for texel the
// encoded pixel.
TEST(RadianceHdrWriter, WhatItWritesReadsBackInItsSpace) {
  test::ScratchFolder dir;
  // 7 and 5: flat; 8: the narrowest run-length scanline (io/radiance_rle.h).
  for (const auto& [width, height] : {std::pair{300, 7}, std::pair{37, 5}, std::pair{8, 3}, std::pair{7, 3}, std::pair{5, 3}}) {
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    const ImageRgbF image = test_image(width, height);
    const auto file = dir / ("a" + std::to_string(width) + ".hdr");
    const RadianceWriteReport report = write_radiance_hdr(file, image, color::color_space("acescg"), "Prism test");
    EXPECT_EQ(report.clipped_pixels, 0u);
    const TextureImage back =
        read_texture_file(file, TextureEncoding::linear, TextureLimits(4096), TextureContent::color_own_gamut);
    EXPECT_EQ(back.texel_space, ColorPickerSpace::acescg);
    EXPECT_EQ(back.primaries_note, "");
    ASSERT_TRUE(back.has_rgbe());
    const std::vector<float> ours = back.linear_values();
    ASSERT_EQ(ours.size(), image.rgb.size());
    for (std::size_t t = 0; t < image.rgb.size() / 3; ++t) {
      const RgbeBytes b = encode_rgbe(image.rgb[3 * t], image.rgb[3 * t + 1], image.rgb[3 * t + 2]);
      ASSERT_EQ(ours[3 * t], decoded(b.r, b.e)) << t;
      ASSERT_EQ(ours[3 * t + 1], decoded(b.g, b.e)) << t;
      ASSERT_EQ(ours[3 * t + 2], decoded(b.b, b.e)) << t;
    }
    const std::string bytes = test::read_bytes(file);
    int w = 0, h = 0, c = 0;
    float* stb = stbi_loadf_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                        static_cast<int>(bytes.size()), &w, &h, &c, 3);
    ASSERT_NE(stb, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, width);
    EXPECT_EQ(h, height);
    EXPECT_EQ(std::vector<float>(stb, stb + ours.size()), ours);
    stbi_image_free(stb);
    // Scanlines from 8 texels wide are run-length encoded: each starts 2, 2, its width (15
    // bits, big-endian). Where rows are long enough for their runs to outweigh the header,
    // the file is smaller than flat texels would be (the flat half of each row is runs).
    const std::string scanline_start{2, 2, static_cast<char>(width >> 8), static_cast<char>(width & 0xff)};
    if (radiance_scanline_is_run_length(static_cast<std::size_t>(width))) {
      EXPECT_NE(bytes.find(scanline_start), std::string::npos);
      if (width >= 32) {
        EXPECT_LT(bytes.size(), 4u * width * height);
      }
    } else {
      EXPECT_EQ(bytes.find(scanline_start), std::string::npos);
    }
  }
}

TEST(RadianceHdrWriter, TheSpectralFilmsXyzIsWrittenAsXyze) {
  test::ScratchFolder dir;
  const ImageRgbF image = test_image(16, 4);
  write_radiance_hdr(dir / "xyz.hdr", image, color::xyz_space("xyz-e", color::kWhiteE), "Prism test");
  const std::string bytes = test::read_bytes(dir / "xyz.hdr");
  const RadianceHeader header =
      read_radiance_header({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, "xyz.hdr");
  EXPECT_TRUE(header.xyz);
  EXPECT_FALSE(header.primaries);
  EXPECT_NE(bytes.find("SOFTWARE=Prism test\n"), std::string::npos);
  // As data, the texels are the XYZ written.
  const std::vector<float> stored =
      read_texture_file(dir / "xyz.hdr", TextureEncoding::linear, TextureLimits(4096), TextureContent::data)
          .linear_values();
  for (std::size_t t = 0; t < stored.size() / 3; ++t) {
    const RgbeBytes b = encode_rgbe(image.rgb[3 * t], image.rgb[3 * t + 1], image.rgb[3 * t + 2]);
    ASSERT_EQ(stored[3 * t + 1], decoded(b.g, b.e)) << t;
  }
  // XYZ relative to another white is not Radiance's XYZ.
  EXPECT_THROW(write_radiance_hdr(dir / "d65.hdr", image, color::color_space("xyz"), "Prism test"), UsageError);
}

// What RGBE cannot hold (a colour outside the space: a negative channel) is counted, and a
// failed write leaves the previous file as it was (io/atomic_file.h).
TEST(RadianceHdrWriter, CountsClippedPixelsAndWritesAtomically) {
  test::ScratchFolder dir;
  ImageRgbF image = test_image(8, 2);
  image.rgb[0] = -0.1f;
  image.rgb[5] = NAN;
  EXPECT_EQ(write_radiance_hdr(dir / "c.hdr", image, color::color_space("srgb"), "Prism test").clipped_pixels, 2u);
  const std::string before = test::read_bytes(dir / "c.hdr");
  WriteFaults::fail_nth_commit(1);
  EXPECT_THROW(write_radiance_hdr(dir / "c.hdr", test_image(9, 3), color::color_space("srgb"), "Prism test"), IoError);
  WriteFaults::clear();
  EXPECT_EQ(test::read_bytes(dir / "c.hdr"), before);
}

}  // namespace
}  // namespace prism
