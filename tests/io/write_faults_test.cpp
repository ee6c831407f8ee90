// A full disk (ENOSPC) while writing: injected through the WriteFaults seam of
// AtomicFile. The error is one line naming the file and the cause, the previous file
// (image or checkpoint) is left exactly as it was, and no temporary file is left behind.
#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "prism/render/checkpoint.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "support/exr_rec709.h"

namespace prism {
namespace {
namespace fs = std::filesystem;

class WriteFaultsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("prism-write-faults-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    WriteFaults::clear();
    fs::remove_all(dir_);
  }
  static std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // Only the named files are left: no temporaries.
  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  // Runs `write`, expecting the one-line ENOSPC IoError naming `target`.
  template <class F>
  void expect_disk_full(const fs::path& target, F&& write) {
    try {
      write();
      FAIL() << "write of " << target << " did not fail";
    } catch (const IoError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_NE(what.find(target.string()), std::string::npos) << what;
      EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
    }
  }
  fs::path dir_;
};

ImageRgbF gradient(int w, int h, float scale) {
  ImageRgbF img{w, h, std::vector<float>(3u * w * h)};
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = scale * static_cast<float>(i % 97);
  return img;
}

using test::kRec709;  // support/exr_rec709.h

TEST_F(WriteFaultsTest, ExrOverwriteOnFullDiskKeepsThePreviousImage) {
  const fs::path out = dir_ / "x.exr";
  write_exr(out, gradient(8, 6, 1.0f), kRec709);
  const std::string before = bytes_of(out);
  WriteFaults::fail_nth_commit(1);
  expect_disk_full(out, [&] { write_exr(out, gradient(8, 6, 2.0f), kRec709); });
  EXPECT_EQ(bytes_of(out), before);
  EXPECT_EQ(files_in_dir(), 1u);
  EXPECT_EQ(read_exr(out).image.rgb, gradient(8, 6, 1.0f).rgb);
}

TEST_F(WriteFaultsTest, PngOnFullDiskLeavesNoFile) {
  const fs::path out = dir_ / "x.png";
  EncodedImage img{4, 4, 3, 8, std::vector<std::uint16_t>(48, 200)};
  WriteFaults::fail_nth_commit(1);
  expect_disk_full(out, [&] { write_png(out, img); });
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(WriteFaultsTest, OnlyTheNthCommitFails) {
  WriteFaults::fail_nth_commit(3);
  for (int i = 1; i <= 4; ++i) {
    const fs::path out = dir_ / fmt::format("f{}.exr", i);
    if (i == 3) {
      expect_disk_full(out, [&] { write_exr(out, gradient(2, 2, 1.0f), kRec709); });
      EXPECT_FALSE(fs::exists(out));
    } else {
      EXPECT_NO_THROW(write_exr(out, gradient(2, 2, 1.0f), kRec709));
    }
  }
  EXPECT_EQ(WriteFaults::commits_seen(), 4);
  EXPECT_EQ(files_in_dir(), 3u);
}

TEST_F(WriteFaultsTest, CheckpointOnFullDiskDuringRenderKeepsTheLastGoodCheckpoint) {
  const Scene scene = make_cornell_box();
  RenderSettings s;
  s.width = 16;
  s.height = 12;
  s.samples_per_pixel = 6;
  s.samples_per_pass = 1;
  const fs::path ckp = dir_ / "r.ckp";
  int written = 0;
  RenderHooks hooks;
  hooks.checkpoint_interval_seconds = 1e-9;  // after every pass
  hooks.on_checkpoint = [&](const Film& film, int next_sample) {
    write_checkpoint(ckp, Checkpoint{42, 0, next_sample, film});
    ++written;
  };
  // Checkpoints after passes 1 and 2 succeed; the disk is full for the third.
  WriteFaults::fail_nth_commit(3);
  expect_disk_full(ckp, [&] { render(scene, s, hooks); });
  EXPECT_EQ(written, 2);
  const Checkpoint c = read_checkpoint(ckp);  // intact and readable
  EXPECT_EQ(c.next_sample, 2);
  EXPECT_EQ(c.fingerprint, 42u);
  EXPECT_EQ(files_in_dir(), 1u);

  // The good checkpoint resumes to the uninterrupted image once there is space again.
  WriteFaults::clear();
  RenderSettings plain = s;
  const RenderResult reference = render(scene, plain);
  const ResumeState resume{c.film, c.next_sample};
  const RenderResult resumed = render(scene, plain, RenderHooks{}, &resume);
  EXPECT_EQ(resumed.film.sums(), reference.film.sums());
  EXPECT_EQ(resumed.film.counts(), reference.film.counts());
}

TEST_F(WriteFaultsTest, OtherErrnoValuesAreReported) {
  const fs::path out = dir_ / "x.exr";
  WriteFaults::fail_nth_commit(1, EIO);
  try {
    write_exr(out, gradient(2, 2, 1.0f), kRec709);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(std::strerror(EIO)), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace prism
