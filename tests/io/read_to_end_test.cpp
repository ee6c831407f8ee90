// read_to_end: whole files in pieces give exactly the bytes reading byte by byte gives,
// whatever the expected size says (right, short, long, unknown), and a stream that fails
// is reported.
#include "prism/io/read_to_end.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/scratch_folder.h"

namespace prism {
namespace {

// 300 000 bytes of every value, with zeros and newlines among them (binary, not text).
std::string sample_bytes() {
  std::string bytes;
  for (int i = 0; i < 300'000; ++i) bytes.push_back(static_cast<char>((i * 131 + i / 977) & 0xff));
  return bytes;
}

TEST(ReadToEnd, GivesTheFileWhateverItsExpectedSizeSays) {
  const test::ScratchFolder folder;
  const std::string bytes = sample_bytes();
  const auto path = folder.write("data.bin", bytes);
  ASSERT_EQ(regular_file_size_or_zero(path), bytes.size());
  // The file's own size, none (64 KiB pieces), too small (more pieces), one byte short,
  // and too large (one short read).
  for (const std::uintmax_t expected : {std::uintmax_t{300'000}, std::uintmax_t{0}, std::uintmax_t{1000},
                                        std::uintmax_t{299'999}, std::uintmax_t{1'000'000}}) {
    std::ifstream as_text(path, std::ios::binary);
    std::string text;
    ASSERT_TRUE(read_to_end(as_text, expected, text)) << expected;
    EXPECT_EQ(text, bytes) << expected;
    std::ifstream as_bytes(path, std::ios::binary);
    std::vector<unsigned char> data;
    ASSERT_TRUE(read_to_end(as_bytes, expected, data)) << expected;
    EXPECT_EQ(data, std::vector<unsigned char>(bytes.begin(), bytes.end())) << expected;
  }
}

TEST(ReadToEnd, ReadsTheRestOfAStreamAndReplacesWhatWasThere) {
  std::istringstream in(sample_bytes());
  in.ignore(12'345);  // partly read already: the rest, not the whole
  std::string out = "left over";
  ASSERT_TRUE(read_to_end(in, 0, out));
  EXPECT_EQ(out, sample_bytes().substr(12'345));
  std::istringstream empty("");
  ASSERT_TRUE(read_to_end(empty, 0, out));
  EXPECT_TRUE(out.empty());
}

TEST(ReadToEnd, AStreamThatFailsIsAnError) {
  std::istringstream in("some bytes");
  in.setstate(std::ios::badbit);
  std::vector<unsigned char> out;
  EXPECT_FALSE(read_to_end(in, 10, out));
}

TEST(ReadToEnd, OnlyRegularFilesHaveASize) {
  const test::ScratchFolder folder;
  EXPECT_EQ(regular_file_size_or_zero(folder.path()), 0u);                  // a directory
  EXPECT_EQ(regular_file_size_or_zero(folder / "missing.bin"), 0u);         // nothing there
  EXPECT_EQ(regular_file_size_or_zero(folder.write("empty.bin", "")), 0u);  // empty
}

}  // namespace
}  // namespace prism
