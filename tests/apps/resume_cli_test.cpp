// End-to-end: `prism render --checkpoint`, interrupted by SIGINT, then `--resume`, gives
// the same pixels as one uninterrupted render; `--sample-range` parts merged with
// `prism merge` give the image of the whole range.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "prism/io/exr.h"
#include "support/cli_test.h"

namespace prism {
namespace {
namespace fs = std::filesystem;

class CliRender : public test::CliTest {};

TEST_F(CliRender, InterruptThenResumeEqualsUninterrupted) {
  const std::string common = "render cornell-box --width 32 --height 32 --seed 3 ";
  ASSERT_EQ(run(common + "--spp 2000 -o " + (dir_ / "full.exr").string()), 0) << log();

  // Start the same render with a checkpoint, interrupt it, then resume.
  const std::string ckp = (dir_ / "render.ckp").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out = (dir_ / "partial.exr").string();
    ::execl(PRISM_CLI, PRISM_CLI, "render", "cornell-box", "--width", "32", "--height", "32", "--seed", "3", "--spp",
            "2000", "--checkpoint", ckp.c_str(), "--checkpoint-every", "0.05", "-o", out.c_str(),
            static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  // Interrupt once the first checkpoint exists: the render is then surely under way with its
  // signal handlers installed (a fixed delay is not enough on a slow or instrumented build,
  // where SIGINT could arrive during start-up and kill the process with the default action).
  int status = 0;
  bool exited = false;
  for (int i = 0; i < 6000 && !fs::exists(ckp); ++i) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!exited) {
    ::kill(pid, SIGINT);
    ::waitpid(pid, &status, 0);
  }
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 0) GTEST_SKIP() << "render finished before the interrupt arrived";
  ASSERT_EQ(WEXITSTATUS(status), 130);
  ASSERT_TRUE(fs::exists(ckp));
  const ExrFile partial = read_exr(dir_ / "partial.exr");
  EXPECT_LT(partial.metadata.ints.at("prism:spp"), 2000);

  ASSERT_EQ(run(common + "--spp 2000 --threads 1 --resume " + ckp + " -o " + (dir_ / "resumed.exr").string()), 0) << log();
  const ExrFile full = read_exr(dir_ / "full.exr");
  const ExrFile resumed = read_exr(dir_ / "resumed.exr");
  EXPECT_EQ(resumed.metadata.ints.at("prism:spp"), 2000);
  EXPECT_TRUE(full.image.rgb == resumed.image.rgb) << "resumed pixels differ from the uninterrupted render";
}

TEST_F(CliRender, ResumeWithDifferentSettingsIsRefused) {
  const std::string ckp = (dir_ / "a.ckp").string();
  ASSERT_EQ(run("render cornell-box --width 16 --height 16 --spp 2 --checkpoint " + ckp + " -o " +
                (dir_ / "a.exr").string()),
            0)
      << log();
  EXPECT_EQ(run("render cornell-box --width 16 --height 16 --spp 4 --seed 9 --resume " + ckp + " -o " +
                (dir_ / "b.exr").string()),
            2);
  EXPECT_NE(log().find("different scene or settings"), std::string::npos) << log();
  EXPECT_FALSE(fs::exists(dir_ / "b.exr"));
}

TEST_F(CliRender, SampleRangesMergeToTheWholeRender) {
  const std::string common = "render cornell-box --width 24 --height 20 ";
  ASSERT_EQ(run(common + "--spp 16 -o " + (dir_ / "whole.exr").string()), 0) << log();
  ASSERT_EQ(run(common + "--sample-range 0:8 -o " + (dir_ / "a.exr").string()), 0) << log();
  ASSERT_EQ(run(common + "--sample-range 8:16 -o " + (dir_ / "b.exr").string()), 0) << log();
  ASSERT_EQ(run("merge " + (dir_ / "a.exr").string() + " " + (dir_ / "b.exr").string() + " -o " +
                (dir_ / "merged.exr").string()),
            0)
      << log();
  const ExrFile whole = read_exr(dir_ / "whole.exr");
  const ExrFile merged = read_exr(dir_ / "merged.exr");
  EXPECT_EQ(merged.metadata.ints.at("prism:spp"), 16);
  ASSERT_EQ(whole.image.rgb.size(), merged.image.rgb.size());
  // Each part's mean is converted from the film's XYZ to RGB and rounded to float before
  // merging. The 3×3 conversion has entries up to ~3.3 in magnitude and cancels, so a
  // channel's rounding error scales with the pixel's largest channel, not with the channel
  // itself: allow 16 float ulps (2e-6) of the pixel's largest channel.
  for (std::size_t px = 0; px + 2 < whole.image.rgb.size(); px += 3) {
    const float scale = std::max({std::abs(whole.image.rgb[px]), std::abs(whole.image.rgb[px + 1]),
                                  std::abs(whole.image.rgb[px + 2])});
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(merged.image.rgb[px + c], whole.image.rgb[px + c], 2e-6f * scale + 1e-30f) << "pixel " << px / 3;
  }
  // Overlapping parts are refused.
  EXPECT_EQ(run("merge " + (dir_ / "a.exr").string() + " " + (dir_ / "a.exr").string() + " -o " +
                (dir_ / "bad.exr").string()),
            2);
  EXPECT_FALSE(fs::exists(dir_ / "bad.exr"));
}

}  // namespace
}  // namespace prism
