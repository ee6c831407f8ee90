#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/io/openexr_header.h"
#include "prism/io/png.h"
#include "prism/scene/loaders/texture_cache.h"
#include "prism/scene/texture.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"
#include "support/exr_rec709.h"
#include "support/exr_test_files.h"

namespace prism {
namespace {

using test::error_of;

using test::kRec709;  // support/exr_rec709.h

TEST(TextureFile, PngDecodesSrgbColourAndLinearAlpha) {
  test::ScratchFolder dir;
  write_png(dir / "a.png", EncodedImage{2, 1, 4, 8, {0, 128, 255, 128, 255, 255, 255, 0}});
  const TextureImage srgb = read_texture_file(dir / "a.png", TextureEncoding::srgb, 32768);
  ASSERT_EQ(srgb.channels, 4);
  EXPECT_EQ(srgb.width, 2);
  EXPECT_FLOAT_EQ(srgb.value(0), 0.0f);
  EXPECT_NEAR(srgb.value(1), 0.2158605f, 1e-6f);  // IEC 61966-2-1 decode of 128/255
  EXPECT_FLOAT_EQ(srgb.value(2), 1.0f);
  EXPECT_NEAR(srgb.value(3), 128.0f / 255.0f, 1e-7f);  // alpha is linear
  // 8-bit images keep their codes (a quarter of the floats' memory), decoded at lookup.
  EXPECT_EQ(srgb.codes, (std::vector<std::uint8_t>{0, 128, 255, 128, 255, 255, 255, 0}));
  EXPECT_TRUE(srgb.texels.empty());
  EXPECT_EQ(srgb.memory_bytes(), 8u);
  const TextureImage linear = read_texture_file(dir / "a.png", TextureEncoding::linear, 32768);
  EXPECT_NEAR(linear.value(1), 128.0f / 255.0f, 1e-7f);
  // 16-bit PNGs keep their precision.
  write_png(dir / "b.png", EncodedImage{1, 1, 1, 16, {32768}});
  const TextureImage sixteen = read_texture_file(dir / "b.png", TextureEncoding::linear, 32768);
  EXPECT_NEAR(sixteen.value(0), 32768.0f / 65535.0f, 1e-7f);
  EXPECT_FALSE(sixteen.has_codes());
}

// RGB JPEGs are decoded by stb_image as RGBA (its SSE2 colour conversion; see stb_header
// in texture_file.cpp) and the alpha dropped: the texels must be exactly stb's own
// three-channel decode, for chroma subsampled 4:2:0 (stb_image_write below quality 90) and
// 4:4:4, at sizes that are not a multiple of the 8-pixel SIMD step, from colour and from
// grey pixels (stb_image_write writes both as three-component JPEGs).
TEST(TextureFile, RgbJpegTexelsAreStbsThreeChannelDecode) {
  test::ScratchFolder dir;
  for (const int channels : {3, 1})
    for (const int quality : {75, 95})
      for (const auto& [width, height] : {std::pair{37, 21}, std::pair{64, 40}}) {
        std::vector<unsigned char> pixels;
        std::uint32_t state = 77u + static_cast<std::uint32_t>(width * quality * channels);
        for (int y = 0; y < height; ++y)
          for (int x = 0; x < width; ++x)
            for (int k = 0; k < channels; ++k) {
              state = state * 1664525u + 1013904223u;  // a gradient with noise: every chroma, clipping at the ends
              pixels.push_back(static_cast<unsigned char>(std::clamp(x * 7 + y * 3 * (k + 1) + int(state >> 27) - 8, 0, 255)));
            }
        std::vector<unsigned char> jpeg;
        ASSERT_TRUE(stbi_write_jpg_to_func(
            [](void* context, void* data, int size) {
              auto* out = static_cast<std::vector<unsigned char>*>(context);
              out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
            },
            &jpeg, width, height, channels, pixels.data(), quality));
        const std::string name = "t" + std::to_string(channels) + "_" + std::to_string(quality) + "_" +
                                 std::to_string(width) + ".jpg";
        dir.write(name, std::string(jpeg.begin(), jpeg.end()));
        int w = 0, h = 0, c = 0;
        unsigned char* expected = stbi_load_from_memory(jpeg.data(), static_cast<int>(jpeg.size()), &w, &h, &c, 0);
        ASSERT_NE(expected, nullptr);
        const std::vector<unsigned char> stb(expected, expected + static_cast<std::size_t>(w) * h * c);
        stbi_image_free(expected);
        ASSERT_EQ(c, 3);
        const TextureImage texture = read_texture_file(dir / name, TextureEncoding::srgb, 32768);
        EXPECT_EQ(texture.width, width);
        EXPECT_EQ(texture.channels, 3);
        EXPECT_EQ(texture.codes, stb) << name;
      }
}

TEST(TextureFile, RadianceHdrAndExrAreLinearFloats) {
  test::ScratchFolder dir;
  // Uncompressed RGBE, value = mantissa · 2^(e − 136): (128, 64, 32) with e = 129 is
  // (1, 0.5, 0.25).
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n";
  hdr += std::string("\x80\x40\x20\x81", 4);
  dir.write("a.hdr", hdr);
  const TextureImage h = read_texture_file(dir / "a.hdr", TextureEncoding::srgb, 32768);
  ASSERT_EQ(h.channels, 3);
  EXPECT_NEAR(h.value(0), 1.0f, 1e-6f);
  EXPECT_NEAR(h.value(1), 0.5f, 1e-6f);
  EXPECT_NEAR(h.value(2), 0.25f, 1e-6f);
  // Kept as RGBE, 4 bytes per texel: texels with and without a normalised mantissa, black,
  // the brightest and the dimmest exponents decode to stb_image's floats exactly (its
  // formula, mantissa · 2^(e − 136); e = 1 gives subnormal floats).
  std::string wide = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 6\n";
  const unsigned char texels[6][4] = {{128, 64, 32, 129}, {3, 100, 7, 140}, {0, 0, 0, 0},
                                      {255, 254, 1, 255}, {200, 9, 0, 1},   {0, 0, 0, 77}};
  for (const auto& t : texels) wide.append(reinterpret_cast<const char*>(t), 4);
  dir.write("b.hdr", wide);
  const TextureImage rgbe = read_texture_file(dir / "b.hdr", TextureEncoding::srgb, 32768);
  ASSERT_TRUE(rgbe.has_rgbe());
  EXPECT_TRUE(rgbe.texels.empty());
  EXPECT_EQ(rgbe.memory_bytes(), 6u * 4u);
  for (int t = 0; t < 6; ++t)
    for (int k = 0; k < 3; ++k) {
      const float expected =
          texels[t][3] == 0 ? 0.0f : texels[t][k] * static_cast<float>(std::ldexp(1.0f, texels[t][3] - 136));
      EXPECT_EQ(rgbe.value(static_cast<std::size_t>(3 * t + k)), expected) << t << " " << k;
      EXPECT_EQ(texel_rgb(rgbe, t, 0)[static_cast<std::size_t>(k)], expected) << t << " " << k;
    }
  EXPECT_EQ(rgbe.linear_values().size(), 18u);
  write_exr(dir / "a.exr", ImageRgbF{1, 1, {2.0f, 3.0f, 4.0f}}, kRec709);
  const TextureImage e = read_texture_file(dir / "a.exr", TextureEncoding::srgb, 32768);
  EXPECT_EQ(e.linear_values(), (std::vector<float>{2.0f, 3.0f, 4.0f}));
}

// An OpenEXR file whose R, G, B are HALF is kept as its halves (6 bytes per texel, the
// budget's figure too), each decoding to the float OpenEXR itself converts it to; a FLOAT
// file stays float (12 bytes per texel).
TEST(TextureFile, HalfFloatOpenExrKeepsItsHalves) {
  test::ScratchFolder dir;
  const std::vector<float> values = {0.0f, 1.0f, -2.5f, 65504.0f, 1e-7f, 0.1f, 3.14159f, 1e5f, 0.33333f,
                                     1024.5f, 6e-5f, 7.0f, 0.5f, 0.25f, 12.0f, 100.0f, 0.001f, 2.0f};
  ExrWriteOptions half_options;
  half_options.pixel_type = ExrPixelType::half;
  write_exr(dir / "half.exr", ImageRgbF{3, 2, values}, kRec709, {}, half_options);
  const TextureImage h = read_texture_file(dir / "half.exr", TextureEncoding::srgb, 32768);
  ASSERT_TRUE(h.has_halves());
  EXPECT_TRUE(h.texels.empty());
  EXPECT_EQ(h.channels, 3);
  EXPECT_EQ(h.memory_bytes(), 3u * 2u * 6u);
  const ExrFile as_floats = read_exr(dir / "half.exr");  // OpenEXR's own half → float
  EXPECT_EQ(h.linear_values(), as_floats.image.rgb);
  EXPECT_NE(h.linear_values(), values);  // the file holds halves: 0.1 and 1e5 did not survive
  const auto half_need = texture_file_memory_need(dir / "half.exr");
  ASSERT_TRUE(half_need);
  EXPECT_EQ(half_need->texel_bytes, 3u * 2u * 6u);

  write_exr(dir / "float.exr", ImageRgbF{3, 2, values}, kRec709);
  const TextureImage f = read_texture_file(dir / "float.exr", TextureEncoding::srgb, 32768);
  EXPECT_FALSE(f.has_halves());
  EXPECT_EQ(f.texels, values);
  const auto float_need = texture_file_memory_need(dir / "float.exr");
  ASSERT_TRUE(float_need);
  EXPECT_EQ(float_need->texel_bytes, 3u * 4u * 6u);
}

// A luminance-only OpenEXR file (channel Y, as greyscale maps are often written) is a
// one-channel grey texture, kept as halves where Y is HALF; it read as black before (R, G,
// B missing). A file with none of R, G, B, Y is an error naming the file, not black.
TEST(TextureFile, LuminanceOnlyOpenExrIsAGreyTexture) {
  test::ScratchFolder dir;
  const std::vector<float> values = {0.0f, 0.5f, 1.0f, 2.0f, 0.25f, 8.0f};
  for (const Imf::PixelType type : {Imf::HALF, Imf::FLOAT}) {
    test::write_single_channel_exr(dir / "y.exr", "Y", type, values);
    const TextureImage t = read_texture_file(dir / "y.exr", TextureEncoding::srgb, 32768);
    EXPECT_EQ(t.channels, 1);
    EXPECT_EQ(t.has_halves(), type == Imf::HALF);
    EXPECT_EQ(t.linear_values(), values);  // all exact in half
    EXPECT_EQ(texel_rgb(t, 2, 1), Vec3f(8.0f));
    const auto need = texture_file_memory_need(dir / "y.exr");
    ASSERT_TRUE(need);
    EXPECT_EQ(need->texel_bytes, 6u * (type == Imf::HALF ? 2u : 4u));
  }
  test::write_single_channel_exr(dir / "z.exr", "Z", Imf::FLOAT, values);
  const std::string error = error_of<IoError>([&] { read_texture_file(dir / "z.exr", TextureEncoding::srgb, 32768); });
  EXPECT_NE(error.find("z.exr"), std::string::npos) << error;
  EXPECT_NE(error.find("no R, G, B or Y channel"), std::string::npos) << error;
  EXPECT_FALSE(texture_file_memory_need(dir / "z.exr"));
}

TEST(TextureFile, RefusesImagesLargerThanTheLimitBeforeDecoding) {
  test::ScratchFolder dir;
  write_png(dir / "a.png", EncodedImage{8, 8, 3, 8, std::vector<std::uint16_t>(8 * 8 * 3, 7)});
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "a.png", TextureEncoding::srgb, 4); })
                .find("8x8 pixels exceeds the limit of 4x4"),
            std::string::npos);
  write_exr(dir / "a.exr", ImageRgbF{8, 8, std::vector<float>(8 * 8 * 3, 1.0f)}, kRec709);
  EXPECT_THROW(read_texture_file(dir / "a.exr", TextureEncoding::srgb, 4), IoError);
  // A PNG whose header claims 40000 × 1 pixels (the default limit is 32768): refused from
  // the header alone, without the pixel data that would have to follow.
  write_png(dir / "b.png", EncodedImage{1, 1, 3, 8, {1, 2, 3}});
  std::string bytes = test::read_bytes(dir / "b.png");
  bytes.replace(16, 4, std::string("\x00\x00\x9c\x40", 4));  // IHDR width, big-endian
  dir.write("huge.png", bytes);
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "huge.png", TextureEncoding::srgb, 32768); })
                .find("40000x1 pixels exceeds the limit"),
            std::string::npos);
}

// A 74-byte PNG may declare 8000 × 8000 RGB pixels: 732 MiB as float texels (below
// stb_image's own 2^30-byte limit on 8-bit samples, which would refuse it first). With a
// memory budget it is refused from its header, before anything is decoded, naming the
// file, and nothing is accounted; a texture that fits is accounted.
TEST(TextureFile, TexelsBeyondTheMemoryBudgetAreRefusedFromTheHeader) {
  test::ScratchFolder dir;
  write_png(dir / "small.png", EncodedImage{2, 2, 3, 8, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}});
  std::string bytes = test::read_bytes(dir / "small.png");
  bytes.replace(16, 8, std::string("\x00\x00\x1f\x40\x00\x00\x1f\x40", 8));  // IHDR 8000 × 8000
  dir.write("bomb.png", bytes);
  MemoryBudget budget(256ull << 20);
  const std::string message =
      error_of<Error>([&] { read_texture_file(dir / "bomb.png", TextureEncoding::srgb, {32768, &budget}); });
  EXPECT_NE(message.find("bomb.png' (8000x8000, 3 channels) needs"), std::string::npos) << message;
  EXPECT_NE(message.find("more than the memory limit of 256 MiB"), std::string::npos) << message;
  EXPECT_EQ(budget.used_bytes(), 0u);
  // An 8-bit image keeps its codes: a byte per sample; a 16-bit one floats.
  read_texture_file(dir / "small.png", TextureEncoding::srgb, {32768, &budget});
  EXPECT_EQ(budget.used_bytes(), 2u * 2u * 3u);
  write_png(dir / "deep.png", EncodedImage{2, 2, 3, 16, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}});
  read_texture_file(dir / "deep.png", TextureEncoding::srgb, {32768, &budget});
  EXPECT_EQ(budget.used_bytes(), 2u * 2u * 3u + 2u * 2u * 3u * sizeof(float));
}

TEST(MemoryBudget, AccountsAndRefusesBeyondTheLimit) {
  MemoryBudget budget(1000);
  budget.reserve(400, 500, "a");  // peak 900: fits; 400 stay
  EXPECT_EQ(budget.used_bytes(), 400u);
  EXPECT_THROW(budget.reserve(300, 301, "b"), Error);  // peak 1001
  EXPECT_EQ(budget.used_bytes(), 400u);
  EXPECT_THROW(budget.reserve(~0ull, 2, "overflow"), Error);
  MemoryBudget unlimited(0);
  unlimited.reserve(~0ull / 2, ~0ull / 4, "anything");
  EXPECT_EQ(unlimited.used_bytes(), ~0ull / 2);
}

TEST(TextureFile, BadFilesAreIoErrors) {
  test::ScratchFolder dir;
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "none.png", TextureEncoding::srgb, 32768); })
                .find("no such file"),
            std::string::npos);
  dir.write("empty.png", "");
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "empty.png", TextureEncoding::srgb, 32768); })
                .find("empty"),
            std::string::npos);
  dir.write("text.png", "GIF89a this is not what the name says");
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "text.png", TextureEncoding::srgb, 32768); })
                .find("wrong magic"),
            std::string::npos);
  // Truncated files of each format.
  write_png(dir / "full.png", EncodedImage{16, 16, 3, 8, std::vector<std::uint16_t>(16 * 16 * 3, 100)});
  const std::string png = test::read_bytes(dir / "full.png");
  dir.write("cut.png", png.substr(0, png.size() / 2));
  EXPECT_THROW(read_texture_file(dir / "cut.png", TextureEncoding::srgb, 32768), IoError);
  write_exr(dir / "full.exr", ImageRgbF{16, 16, std::vector<float>(16 * 16 * 3, 1.0f)}, kRec709);
  const std::string exr = test::read_bytes(dir / "full.exr");
  dir.write("cut.exr", exr.substr(0, exr.size() / 2));
  EXPECT_THROW(read_texture_file(dir / "cut.exr", TextureEncoding::srgb, 32768), IoError);
  dir.write("cut.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n\x80\x40");
  EXPECT_THROW(read_texture_file(dir / "cut.hdr", TextureEncoding::srgb, 32768), IoError);
  dir.write("cut.jpg", std::string("\xff\xd8\xff\xe0\x00\x10JFIF", 10));
  EXPECT_THROW(read_texture_file(dir / "cut.jpg", TextureEncoding::srgb, 32768), IoError);
  std::filesystem::create_directories(dir / "folder.png");
  EXPECT_THROW(read_texture_file(dir / "folder.png", TextureEncoding::srgb, 32768), IoError);
}

TEST(TextureFile, CacheLoadsEachFileOncePerEncodingAndAddressing) {
  test::ScratchFolder dir;
  write_png(dir / "a.png", EncodedImage{1, 1, 3, 8, {128, 128, 128}});
  Scene scene;
  loaders::TextureCache cache(scene, LoadOptions{});
  const int a = cache.load(dir / "a.png", TextureEncoding::srgb);
  EXPECT_EQ(cache.load(dir.path() / "." / "a.png", TextureEncoding::srgb), a);
  const int linear = cache.load(dir / "a.png", TextureEncoding::linear);
  EXPECT_NE(linear, a);
  const int clamped = cache.load(dir / "a.png", TextureEncoding::srgb, TextureWrap::clamp, TextureWrap::clamp);
  EXPECT_NE(clamped, a);
  EXPECT_EQ(scene.textures.size(), 3u);
  cache.finish();
  EXPECT_EQ(cache.files_read(), 3u);
  EXPECT_EQ(scene.textures[static_cast<std::size_t>(clamped)].wrap_u, TextureWrap::clamp);
}

}  // namespace
}  // namespace prism

namespace prism {
namespace {

// The IoError read_texture_file gives a fuzz regression input kept in tests/scene/loaders/data.
std::string regression_input_error(std::string_view file_name, TextureEncoding encoding) {
  const std::filesystem::path file = std::filesystem::path(PRISM_SOURCE_DIR) / "tests/scene/loaders/data" / file_name;
  EXPECT_TRUE(std::filesystem::exists(file)) << file;
  return error_of<IoError>([&] { read_texture_file(file, encoding, 32768); });
}

TEST(TextureFile, OpenExrHeaderClaimingMoreThanTheFileHoldsIsRefusedBeforeAllocating) {
  // Regression (fuzz_image_readers): a 610-byte EXR whose string attribute declares ~2 GB;
  // OpenEXR 3.1 allocated it before reading. Now refused by our own header walk.
  EXPECT_NE(regression_input_error("fuzz_exr_huge_attribute.exr", TextureEncoding::linear)
                .find("corrupt or truncated OpenEXR header"),
            std::string::npos);
}

TEST(TextureFile, OpenExrAttributeOfAFixedSizeTypeMustDeclareThatSize) {
  // Regression (fuzz_image_readers): a 742-byte EXR whose float attribute declares 247 bytes.
  // OpenEXR reads 4 and carries on inside the value, where it finds an "attribute" of 1.7 GB
  // and allocates it; our walk, skipping 247 bytes, saw nothing wrong. Known types must now
  // declare their own size.
  const std::string message = regression_input_error("fuzz_exr_fixed_size_attribute.exr", TextureEncoding::linear);
  EXPECT_NE(message.find("attribute 'pix-lAspectRatio' of type float claims 247 bytes, not 4"), std::string::npos)
      << message;
  // Files OpenEXR itself writes still pass the walk.
  test::ScratchFolder dir;
  write_exr(dir / "ok.exr", ImageRgbF{2, 2, std::vector<float>(2 * 2 * 3, 0.5f)}, kRec709);
  EXPECT_EQ(read_texture_file(dir / "ok.exr", TextureEncoding::linear, 32768).width, 2);
}

TEST(TextureFile, OpenExrNamesLongerThanOpenExrReadsAreRefused) {
  // Regression input found by fuzz_image_readers: a 358-byte EXR with a 42-character
  // attribute name and no long-names flag. OpenEXR reads 31 characters of it and takes the
  // rest for the type name, so it parses other attributes than our walk did, and allocated
  // a string attribute of 1.7 GB. (Its channel list also lacks its final null, which the
  // walk now finds first: TextureFile.OpenExrValuesReadByContentMustFillTheirSize.)
  EXPECT_NE(regression_input_error("fuzz_exr_long_attribute_name.exr", TextureEncoding::linear)
                .find("corrupt or truncated OpenEXR header"),
            std::string::npos);
  // The name alone: a valid file with a 42-character attribute put first.
  test::ScratchFolder dir;
  write_exr(dir / "ok.exr", ImageRgbF{2, 2, std::vector<float>(2 * 2 * 3, 0.5f)}, kRec709);
  std::string bytes = test::read_bytes(dir / "ok.exr");
  std::string attribute = std::string(42, 'a') + '\0' + "string" + '\0';
  test::append<std::int32_t>(attribute, {4});
  attribute += "abcd";
  dir.write("long.exr", bytes.substr(0, 8) + attribute + bytes.substr(8));
  const std::string message =
      error_of<IoError>([&] { read_texture_file(dir / "long.exr", TextureEncoding::linear, 32768); });
  EXPECT_NE(message.find("a name of 42 characters, over OpenEXR's 31 without the long-names flag"), std::string::npos)
      << message;
  // Attribute names of 31 characters, the most OpenEXR writes without the flag, still read.
  ExrMetadata meta;
  meta.strings["prism:aaaaaaaaaaaaaaaaaaaaaaaaa"] = "31 characters";
  ASSERT_EQ(std::string("prism:aaaaaaaaaaaaaaaaaaaaaaaaa").size(), 31u);
  write_exr(dir / "ok31.exr", ImageRgbF{2, 2, std::vector<float>(2 * 2 * 3, 0.5f)}, kRec709, meta);
  EXPECT_EQ(read_texture_file(dir / "ok31.exr", TextureEncoding::linear, 32768).width, 2);
}

// OpenEXR reads a chlist, a stringvector and a preview by their content, not their declared
// size: a value whose content says otherwise puts OpenEXR out of step with the walk.
TEST(TextureFile, OpenExrValuesReadByContentMustFillTheirSize) {
  // Regression input found by fuzz_image_readers: a 2.7 kB EXR whose second channel list
  // declares 55 bytes for three entries and no final null. OpenEXR read on into the next
  // attribute and later allocated a 1.6 GB string.
  const std::string message = regression_input_error("fuzz_exr_chlist_without_end.exr", TextureEncoding::linear);
  EXPECT_NE(message.find("attribute 'channels' of type chlist: a channel list that does not end where its size says"),
            std::string::npos)
      << message;
  // A string vector whose string claims more than the value holds, and a preview whose
  // size says more pixels than it holds: OpenEXR allocates what they claim. Each is put
  // first in a valid file's header (its pixel data then lies past the offsets the file
  // records, so only the walk's verdict is checked).
  test::ScratchFolder dir;
  write_exr(dir / "ok.exr", ImageRgbF{2, 2, std::vector<float>(2 * 2 * 3, 0.5f)}, kRec709);
  const std::string bytes = test::read_bytes(dir / "ok.exr");
  const auto walk = [&](const std::string& name, const std::string& type, std::initializer_list<std::int32_t> words,
                        const std::string& tail) {
    std::string attribute = name + '\0' + type + '\0';
    test::append<std::int32_t>(attribute, words);
    const std::string file = bytes.substr(0, 8) + attribute + tail + bytes.substr(8);
    try {
      check_openexr_header({reinterpret_cast<const unsigned char*>(file.data()), file.size()}, 32768, "t.exr");
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("passed");
  };
  EXPECT_NE(walk("notes", "stringvector", {8, 1000000000}, "abcd").find("a string of 1000000000 bytes in a string vector of 8"),
            std::string::npos);
  EXPECT_NE(walk("preview", "preview", {12, 30000, 30000}, "abcd").find("a preview of 30000x30000 pixels in 12 bytes"),
            std::string::npos);
  // Well-formed ones pass: a string vector of two strings ("ab", "cde"), a 1×1 preview.
  std::string two_strings = "ab";
  test::append<std::int32_t>(two_strings, {3});
  two_strings += "cde";
  EXPECT_EQ(walk("notes", "stringvector", {13, 2}, two_strings), "passed");
  EXPECT_EQ(walk("preview", "preview", {12, 1, 1}, "rgba"), "passed");
}

TEST(TextureFile, JpegHuffmanTableWithTooManyCodesIsRefusedBeforeStbImage) {
  // Regression (fuzz_image_readers, found by the CI's fuzz-smoke run): a 684-byte JPEG whose
  // DHT counts sum past 256; stb_image wrote past its 257-entry size table (UBSan
  // index-out-of-bounds in stbi__build_huffman). Now refused by our own marker walk.
  EXPECT_NE(regression_input_error("fuzz_jpeg_huffman_overflow.jpg", TextureEncoding::srgb)
                .find("corrupt JPEG (Huffman table with"),
            std::string::npos);
  // A valid JPEG still decodes (the fuzz corpus' seed image).
  const TextureImage ok = read_texture_file(std::filesystem::path(PRISM_SOURCE_DIR) / "fuzz/corpus/fuzz_image_readers/tiny.jpg",
                                            TextureEncoding::srgb, 32768);
  EXPECT_GT(ok.width, 0);
}

TEST(TextureFile, JpegScanUsingAnUndefinedHuffmanTableIsRefusedBeforeStbImage) {
  // Regression (fuzz_image_readers, CI fuzz-smoke): a 661-byte baseline JPEG whose first scan
  // selects AC table 3, which no DHT defines; stb_image decoded with its uninitialised table
  // (UBSan: index 637 out of bounds for 'stbi_uc[256]' in stbi__jpeg_huff_decode).
  EXPECT_NE(regression_input_error("fuzz_jpeg_undefined_huffman_table.jpg", TextureEncoding::srgb)
                .find("corrupt JPEG (scan uses AC Huffman table 3 before it is defined)"),
            std::string::npos);
}

TEST(TextureFile, SequentialJpegScanNeedsBothHuffmanTablesWhateverItsSpectralSelection) {
  // Regression (fuzz_image_readers, CI fuzz-smoke): a 715-byte baseline JPEG whose scan
  // declares Ss = Se = 0 (valid only in progressive frames) and selects AC table 3, which no
  // DHT defines. The walk took Se = 0 to mean "no AC coefficients", but stb_image decodes
  // whole blocks in a sequential frame and read its uninitialised table (UBSan: index -1
  // out of bounds for 'stbi_uc[256]' in stbi__jpeg_huff_decode).
  EXPECT_NE(regression_input_error("fuzz_jpeg_sequential_scan_without_ac_table.jpg", TextureEncoding::srgb)
                .find("corrupt JPEG (scan uses AC Huffman table 3 before it is defined)"),
            std::string::npos);
}

TEST(TextureFile, PngWithAnEmptyIdatChunkIsReadWithoutIt) {
  // Regression (fuzz_image_readers, CI fuzz-smoke): an empty first IDAT made stb_image memcpy
  // to a null buffer (UBSan). Empty IDATs are dropped first; the file either decodes or is a
  // clean IoError, never undefined behaviour (checked under UBSan by the asan preset).
  const std::filesystem::path file =
      std::filesystem::path(PRISM_SOURCE_DIR) / "tests/scene/loaders/data/fuzz_png_empty_idat.png";
  ASSERT_TRUE(std::filesystem::exists(file));
  try {
    read_texture_file(file, TextureEncoding::srgb, 32768);
  } catch (const IoError&) {
  }
  // A valid PNG with an empty IDAT chunk inserted before its data decodes to the same texels.
  test::ScratchFolder dir;
  write_png(dir / "a.png", EncodedImage{2, 1, 3, 8, {10, 20, 30, 40, 50, 60}});
  std::string bytes = test::read_bytes(dir / "a.png");
  const std::size_t idat = bytes.find("IDAT") - 4;
  bytes.insert(idat, std::string("\x00\x00\x00\x00IDAT\x35\xaf\x06\x1e", 12));  // CRC-32 of "IDAT"
  dir.write("empty_idat.png", bytes);
  EXPECT_EQ(read_texture_file(dir / "empty_idat.png", TextureEncoding::linear, 32768).linear_values(),
            read_texture_file(dir / "a.png", TextureEncoding::linear, 32768).linear_values());
}

TEST(TextureFile, PngChunkHeaderAtTheEndOfTheFileIsCheckedToo) {
  // Regression (fuzz_image_readers, CI fuzz-smoke): a 76-byte PNG ending in an IDAT header
  // that declares 0x52000000 bytes and then 3 more bytes. The chunk walk only looked at
  // chunks with 12 bytes left (header and CRC), so this one reached stb_image, which
  // reallocated 2 GB from the header alone (libFuzzer: out-of-memory).
  EXPECT_NE(regression_input_error("fuzz_png_truncated_chunk_header.png", TextureEncoding::srgb)
                .find("corrupt or truncated PNG (a chunk claims 1375731712 bytes"),
            std::string::npos);
}

TEST(TextureFile, PngChunkClaimingMoreThanTheFileHoldsIsRefusedBeforeStbImage) {
  // Regression (fuzz_image_readers): an IDAT declaring ~2 GB made stb_image realloc 2 GB
  // before reading. Refused by our own chunk walk, before any allocation.
  test::ScratchFolder dir;
  write_png(dir / "a.png", EncodedImage{2, 1, 3, 8, {10, 20, 30, 40, 50, 60}});
  std::string bytes = test::read_bytes(dir / "a.png");
  bytes.replace(bytes.find("IDAT") - 4, 4, std::string("\x7f\xff\xff\xf0", 4));
  dir.write("huge_idat.png", bytes);
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "huge_idat.png", TextureEncoding::srgb, 32768); })
                .find("corrupt or truncated PNG"),
            std::string::npos);
}

TEST(TextureFile, OpenExrDataWindowIsCheckedBeforeOpenExrSeesIt) {
  test::ScratchFolder dir;
  write_exr(dir / "a.exr", ImageRgbF{2, 2, std::vector<float>(12, 1.0f)}, kRec709);
  std::string bytes = test::read_bytes(dir / "a.exr");
  const std::size_t at = bytes.find("dataWindow");
  ASSERT_NE(at, std::string::npos);
  // name\0 "box2i"\0 size(4) then xMin yMin xMax yMax: make yMax 2^30.
  const std::size_t y_max = at + std::string_view("dataWindow").size() + 1 + 6 + 4 + 12;
  bytes.replace(y_max, 4, std::string("\x00\x00\x00\x40", 4));
  dir.write("tall.exr", bytes);
  EXPECT_NE(error_of<IoError>([&] { read_texture_file(dir / "tall.exr", TextureEncoding::linear, 32768); })
                .find("exceeds the limit"),
            std::string::npos);
}

}  // namespace
}  // namespace prism
