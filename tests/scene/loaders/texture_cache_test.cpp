// The loaders' texture cache decodes the images asked for since the last sync together
// (texture_cache.h); what a loader gets must be what decoding each image when asked for
// gives: the same textures at the same indices, and the same first error.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "prism/scene/loaders/texture_cache.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

using test::error_of;

// Four 16 × 16 RGB PNGs of different codes.
std::vector<std::filesystem::path> four_images(const test::ScratchFolder& dir) {
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < 4; ++i) {
    std::vector<std::uint16_t> codes(16 * 16 * 3);
    for (std::size_t k = 0; k < codes.size(); ++k) codes[k] = static_cast<std::uint16_t>((k * 7 + 50 * i) % 256);
    files.push_back(dir / fmt::format("t{}.png", i));
    write_png(files.back(), EncodedImage{16, 16, 3, 8, codes});
  }
  return files;
}

TEST(TextureCache, ImagesAskedForTogetherAreThoseDecodedOneByOne) {
  test::ScratchFolder dir;
  const auto files = four_images(dir);
  Scene scene;
  loaders::TextureCache cache(scene, LoadOptions{});
  std::vector<int> indices;
  for (const auto& f : files) indices.push_back(cache.load(f, TextureEncoding::srgb, TextureWrap::clamp));
  EXPECT_EQ(indices, (std::vector<int>{0, 1, 2, 3}));
  // Until the sync an entry holds its name and addressing only.
  ASSERT_EQ(scene.textures.size(), 4u);
  EXPECT_EQ(scene.textures[2].name, "t2.png");
  EXPECT_EQ(scene.textures[2].sample_count(), 0u);
  EXPECT_EQ(cache.files_read(), 0u);
  cache.finish();
  EXPECT_EQ(cache.files_read(), 4u);
  EXPECT_EQ(cache.parallel_batches(), 1u);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const TextureImage alone = read_texture_file(files[i], TextureEncoding::srgb, 32768);
    EXPECT_EQ(scene.textures[i].codes, alone.codes) << i;
    EXPECT_EQ(scene.textures[i].width, 16);
    EXPECT_EQ(scene.textures[i].name, files[i].filename().string());
    EXPECT_EQ(scene.textures[i].wrap_u, TextureWrap::clamp);
    EXPECT_EQ(scene.textures[i].wrap_v, TextureWrap::repeat);
  }
  // Asked for again: the same entry, nothing decoded.
  EXPECT_EQ(cache.load(files[1], TextureEncoding::srgb, TextureWrap::clamp), 1);
  cache.finish();
  EXPECT_EQ(cache.files_read(), 4u);
  // image() is a sync: a later request is decoded before it returns.
  const int later = cache.load(files[0], TextureEncoding::linear);
  EXPECT_EQ(cache.image(later).codes, scene.textures[0].codes);
  EXPECT_EQ(cache.files_read(), 5u);
}

// One at a time an image's decoder buffer sits beside the texels decoded before it only;
// together every buffer is held at once. A budget that holds the first but not the second
// decodes one at a time, and every image still loads.
TEST(TextureCache, ImagesThatFitOnlyOneAtATimeAreDecodedOneAtATime) {
  test::ScratchFolder dir;
  const auto files = four_images(dir);
  constexpr std::uint64_t kCodes = 16 * 16 * 3;  // kept per image, and the decoder's buffer again
  for (const bool roomy : {true, false}) {
    MemoryBudget budget(roomy ? 8 * kCodes : 5 * kCodes);
    Scene scene;
    loaders::TextureCache cache(scene, LoadOptions{.memory_budget = &budget});
    for (const auto& f : files) cache.load(f, TextureEncoding::srgb);
    cache.finish();
    EXPECT_EQ(cache.parallel_batches(), roomy ? 1u : 0u);
    EXPECT_EQ(budget.used_bytes(), 4 * kCodes);
    for (std::size_t i = 0; i < files.size(); ++i)
      EXPECT_EQ(scene.textures[i].codes, read_texture_file(files[i], TextureEncoding::srgb, 32768).codes);
  }
}

// OpenEXR images count in the budget check too (their size from the header the reader
// walks first): a batch with one is still decoded together when it all fits.
TEST(TextureCache, OpenExrImagesJoinTheBatch) {
  test::ScratchFolder dir;
  const auto files = four_images(dir);
  write_exr(dir / "sky.exr", ImageRgbF{8, 4, std::vector<float>(8 * 4 * 3, 0.5f)},
            ExrChromaticities{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f});
  EXPECT_EQ(texture_file_memory_need(dir / "sky.exr")->texel_bytes, 8u * 4u * 3u * sizeof(float));
  MemoryBudget budget(1u << 20);
  Scene scene;
  loaders::TextureCache cache(scene, LoadOptions{.memory_budget = &budget});
  cache.load(files[0], TextureEncoding::srgb);
  const int sky = cache.load(dir / "sky.exr", TextureEncoding::srgb);
  cache.finish();
  EXPECT_EQ(cache.parallel_batches(), 1u);
  EXPECT_EQ(scene.textures[static_cast<std::size_t>(sky)].linear_values(), std::vector<float>(8 * 4 * 3, 0.5f));
  EXPECT_EQ(budget.used_bytes(), 16u * 16u * 3u + 8u * 4u * 3u * sizeof(float));
}

// Errors are those of decoding one image after another: the first bad image in request
// order, with the context its loader gave, every time; checks run in the same order.
TEST(TextureCache, TheFirstFailureInRequestOrderIsReported) {
  test::ScratchFolder dir;
  const auto files = four_images(dir);
  dir.write("truncated.png", "\x89PNG\r\n\x1a\n truncated");
  dir.write("garbage.png", "not an image at all");
  for (int run = 0; run < 8; ++run) {
    Scene scene;
    loaders::TextureCache cache(scene, LoadOptions{});
    cache.load(files[0], TextureEncoding::srgb);
    cache.load(dir / "truncated.png", TextureEncoding::srgb, TextureWrap::repeat, TextureWrap::repeat,
               "scene.obj: material 'a' map_Kd");
    cache.load(dir / "garbage.png", TextureEncoding::srgb);
    const std::string message = error_of<IoError>([&] { cache.finish(); });
    EXPECT_EQ(message.rfind("scene.obj: material 'a' map_Kd: cannot read image", 0), 0u) << message;
    EXPECT_NE(message.find("truncated.png"), std::string::npos) << message;
  }
  // A check refusing an earlier image comes before a later image's decode error.
  Scene scene;
  loaders::TextureCache cache(scene, LoadOptions{});
  cache.load(files[0], TextureEncoding::linear, TextureWrap::repeat, TextureWrap::repeat, {},
             [](const TextureImage&) { throw SceneError("refused by its check"); });
  cache.load(dir / "garbage.png", TextureEncoding::srgb);
  EXPECT_EQ(error_of<SceneError>([&] { cache.finish(); }), "refused by its check");
}

// A loader that fails after asking for a bad image reports the image, as it would have
// failed there first decoding one image at a time; with no bad image, its own error.
TEST(TextureCache, AnEarlierBadImageComesBeforeTheLoadersLaterError) {
  test::ScratchFolder dir;
  const auto files = four_images(dir);
  dir.write("garbage.png", "not an image at all");
  const auto later_error = std::make_exception_ptr(SceneError("scene.pbrt:40: a later error"));
  {
    Scene scene;
    loaders::TextureCache cache(scene, LoadOptions{});
    cache.load(files[0], TextureEncoding::srgb);
    cache.load(dir / "garbage.png", TextureEncoding::srgb, TextureWrap::repeat, TextureWrap::repeat, "scene.pbrt:3: Texture");
    const std::string message = error_of<IoError>([&] { cache.rethrow_first_error(later_error); });
    EXPECT_EQ(message.rfind("scene.pbrt:3: Texture: cannot read image", 0), 0u) << message;
  }
  Scene scene;
  loaders::TextureCache cache(scene, LoadOptions{});
  cache.load(files[0], TextureEncoding::srgb);
  EXPECT_EQ(error_of<SceneError>([&] { cache.rethrow_first_error(later_error); }), "scene.pbrt:40: a later error");
}

}  // namespace
}  // namespace prism
