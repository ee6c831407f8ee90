// Every OpenEXR read walks the header before OpenEXR does (io/openexr_header.h): the fuzz
// regression inputs that made OpenEXR allocate gigabytes are refused by `prism tonemap`,
// `merge` and `--resume` (io/exr.h's readers) as they are by the texture loader, and a
// file whose header is larger than the first MiB the walk reads still reads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/io/openexr_header.h"
#include "scene/loaders/loader_test_files.h"
#include "support/exr_rec709.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

using test::kRec709;  // support/exr_rec709.h

TEST(OpenExrHeader, TheIoReadersRefuseTheFuzzRegressionsBeforeOpenExrAllocates) {
  const std::filesystem::path data = std::filesystem::path(PRISM_SOURCE_DIR) / "tests/scene/loaders/data";
  const std::pair<const char*, const char*> files[] = {
      {"fuzz_exr_huge_attribute.exr", "attribute 'prism:transport' claims 1952514092 bytes"},
      {"fuzz_exr_fixed_size_attribute.exr", "of type float claims 247 bytes, not 4"},
      {"fuzz_exr_long_attribute_name.exr", "attribute 'channels' of type chlist"},
      {"fuzz_exr_chlist_without_end.exr", "a channel list that does not end where its size says"},
  };
  for (const auto& entry : files) {
    const char* file = entry.first;  // (clang 14 cannot capture a structured binding)
    const char* why = entry.second;
    // Unchecked, these reach OpenEXR, which allocates 1.6–2 GB and then fails
    // (std::bad_alloc under a memory limit).
    const std::string message = test::error_of<IoError>([&] { read_exr(data / file); });
    EXPECT_NE(message.find("corrupt or truncated OpenEXR header"), std::string::npos) << file << ": " << message;
    EXPECT_NE(message.find(why), std::string::npos) << file << ": " << message;
    EXPECT_NE(test::error_of<IoError>([&] { read_exr_vector_layer(data / file, "N"); }).find("OpenEXR header"),
              std::string::npos)
        << file;
  }
}

// A header of 1.5 MiB (a long string attribute) runs past the MiB the walk reads first;
// the whole file then decides, and the file reads.
TEST(OpenExrHeader, AHeaderLargerThanTheFirstMibStillReads) {
  test::ScratchFolder dir;
  ExrMetadata meta;
  meta.strings["prism:notes"] = std::string(1536 * 1024, 'x');
  write_exr(dir / "big_header.exr", ImageRgbF{2, 1, {0.5f, 0.25f, 0.125f, 1.0f, 2.0f, 4.0f}}, kRec709, meta);
  ASSERT_GT(std::filesystem::file_size(dir / "big_header.exr"), 1u << 20);
  const ExrFile read = read_exr(dir / "big_header.exr");
  EXPECT_EQ(read.image.rgb, (std::vector<float>{0.5f, 0.25f, 0.125f, 1.0f, 2.0f, 4.0f}));
  EXPECT_EQ(check_openexr_file_header(dir / "big_header.exr").width, 2);
  // Cut inside that attribute, the same file is refused by the walk.
  const std::string bytes = [&] {
    std::ifstream in(dir / "big_header.exr", std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  {
    std::ofstream out(dir / "cut.exr", std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(1200 * 1024));
  }
  EXPECT_NE(test::error_of<IoError>([&] { read_exr(dir / "cut.exr"); }).find("corrupt or truncated OpenEXR header"),
            std::string::npos);
}

}  // namespace
}  // namespace prism
