// End-to-end: `prism render --aov` writes the AOVs as OpenEXR layers beside an unchanged
// beauty, `prism merge` carries them, and `--view normal` shows the normal AOV.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "prism/io/exr.h"
#include "support/cli_test.h"
#include "prism/io/png.h"

namespace prism {
namespace {
namespace fs = std::filesystem;

class AovCli : public test::CliTest {};

// Channel names as OpenEXR itself reads them, not through Prism's reader.
std::set<std::string> channel_names(const std::string& file) {
  Imf::InputFile in(file.c_str());
  std::set<std::string> names;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) names.insert(it.name());
  return names;
}

std::set<std::string> layer_names(const std::string& file) {
  Imf::InputFile in(file.c_str());
  std::set<std::string> layers;
  in.header().channels().layers(layers);
  return layers;
}

const std::string kRender = "render cornell-box --width 24 --height 20 --seed 2 ";

TEST_F(AovCli, LayersHaveOpenExrNamesAndTheBeautyIsUnchanged) {
  ASSERT_EQ(run(kRender + "--spp 2 --aov albedo,normal,depth -o " + path("aov.exr")), 0) << log();
  ASSERT_EQ(run(kRender + "--spp 2 -o " + path("plain.exr")), 0) << log();
  EXPECT_EQ(channel_names(path("aov.exr")), (std::set<std::string>{"R", "G", "B", "albedo.R", "albedo.G", "albedo.B",
                                                                   "N.x", "N.y", "N.z", "Z", "Z.coverage"}));
  EXPECT_EQ(layer_names(path("aov.exr")), (std::set<std::string>{"albedo", "N", "Z"}));
  EXPECT_EQ(channel_names(path("plain.exr")), (std::set<std::string>{"R", "G", "B"}));
  const ExrFile aov = read_exr(path("aov.exr")), plain = read_exr(path("plain.exr"));
  EXPECT_EQ(aov.image.rgb, plain.image.rgb) << "--aov changed the beauty";
  EXPECT_EQ(aov.metadata.strings.at("prism:aovs"), "albedo,normal,depth");

  ASSERT_EQ(run(kRender + "--spp 2 --aov depth -o " + path("depth.exr")), 0) << log();
  EXPECT_EQ(channel_names(path("depth.exr")), (std::set<std::string>{"R", "G", "B", "Z", "Z.coverage"}));
  // Normals are unit vectors wherever every sample hit the same plane; depths are positive.
  const auto n = read_exr_channels(path("aov.exr"), {"N.x", "N.y", "N.z"});
  const auto z = read_exr_channels(path("aov.exr"), {"Z"});
  ASSERT_TRUE(n && z);
  for (float d : *z) EXPECT_GT(d, 0.0f);
  // Which pixels have all their samples on one plane depends on the sampler's numbers, so
  // count them: no average of unit vectors is longer than 1, and most pixels of the box
  // (walls, floor, blocks) see a single plane.
  int unit = 0;
  for (std::size_t p = 0; p < z->size(); ++p) {
    const double length = std::hypot((*n)[3 * p], (*n)[3 * p + 1], (*n)[3 * p + 2]);
    EXPECT_LE(length, 1.0 + 1e-6) << "pixel " << p;
    if (std::abs(length - 1.0) < 1e-6) ++unit;
  }
  EXPECT_GT(unit, static_cast<int>(z->size()) / 2);
}

TEST_F(AovCli, MergedPartsCarryTheAovs) {
  const std::string aov = "--aov normal,depth,albedo ";
  ASSERT_EQ(run(kRender + aov + "--spp 4 -o " + path("full.exr")), 0) << log();
  ASSERT_EQ(run(kRender + aov + "--sample-range 0:1 -o " + path("a.exr")), 0) << log();
  ASSERT_EQ(run(kRender + aov + "--sample-range 1:4 -o " + path("b.exr")), 0) << log();
  ASSERT_EQ(run("merge " + path("a.exr") + " " + path("b.exr") + " -o " + path("merged.exr")), 0) << log();
  EXPECT_EQ(channel_names(path("merged.exr")), channel_names(path("full.exr")));
  for (const std::vector<std::string>& names : {std::vector<std::string>{"albedo.R", "albedo.G", "albedo.B"},
                                                std::vector<std::string>{"N.x", "N.y", "N.z"},
                                                std::vector<std::string>{"Z"}, std::vector<std::string>{"Z.coverage"}}) {
    const auto merged = read_exr_channels(path("merged.exr"), names);
    const auto full = read_exr_channels(path("full.exr"), names);
    const auto a = read_exr_channels(path("a.exr"), names), b = read_exr_channels(path("b.exr"), names);
    ASSERT_TRUE(merged && full && a && b);
    for (std::size_t i = 0; i < full->size(); ++i) {
      // Weighted means of float parts formed in double: a few float ulps of the largest
      // magnitude involved (normals are signed, so parts can cancel), as in
      // MergePartialRenders.AovsMergeToTheSingleRendersAovs.
      const float want = (*full)[i], got = (*merged)[i];
      const float scale = std::max({std::abs(want), std::abs((*a)[i]), std::abs((*b)[i])});
      EXPECT_TRUE(got == want || std::abs(got - want) <= 4e-7f * scale + 1e-30f)
          << names.front() << " at " << i << ": " << got << " vs " << want;
    }
  }
  // Parts with different AOV sets were rendered with different fingerprints: refused.
  ASSERT_EQ(run(kRender + "--sample-range 4:5 -o " + path("c.exr")), 0) << log();
  EXPECT_EQ(run("merge " + path("a.exr") + " " + path("c.exr") + " -o " + path("bad.exr")), 2) << log();
}

TEST_F(AovCli, VarianceLayerMergesToTheWholeRendersVariance) {
  // --aov variance writes variance.R/G/B (the beauty's pixel-mean variance in the EXR's
  // space); merging parts 0:3 and 3:8 reproduces the 8-sample render's layer. Bound: the
  // parts' means and variances are floats, and the merge adds n(m − m̄)² terms of float
  // means, so 1e-4 relative (docs/aovs.md; same bound as the library test).
  const std::string aov = "--aov variance ";
  ASSERT_EQ(run(kRender + aov + "--spp 8 -o " + path("full.exr")), 0) << log();
  ASSERT_EQ(run(kRender + aov + "--sample-range 0:3 -o " + path("a.exr")), 0) << log();
  ASSERT_EQ(run(kRender + aov + "--sample-range 3:8 -o " + path("b.exr")), 0) << log();
  ASSERT_EQ(run("merge " + path("a.exr") + " " + path("b.exr") + " -o " + path("merged.exr")), 0) << log();
  EXPECT_EQ(channel_names(path("full.exr")), (std::set<std::string>{"R", "G", "B", "variance.R", "variance.G", "variance.B"}));
  const std::vector<std::string> names{"variance.R", "variance.G", "variance.B"};
  const auto merged = read_exr_channels(path("merged.exr"), names), full = read_exr_channels(path("full.exr"), names);
  ASSERT_TRUE(merged && full);
  float largest = 0.0f;
  for (std::size_t i = 0; i < full->size(); ++i) {
    EXPECT_NEAR((*merged)[i], (*full)[i], 1e-4f * (*full)[i] + 1e-30f) << "value " << i;
    largest = std::max(largest, (*full)[i]);
  }
  EXPECT_GT(largest, 0.0f);
}

TEST_F(AovCli, ViewNormalShowsTheNormalAov) {
  // --view normal turns the normal AOV on, so the EXR written beside the PNG holds it.
  ASSERT_EQ(run(kRender + "--spp 1 --view normal -o " + path("n.exr") + " -o " + path("n.png")), 0) << log();
  const auto n = read_exr_channels(path("n.exr"), {"N.x", "N.y", "N.z"});
  ASSERT_TRUE(n) << "no N layer in the EXR";
  const PngFile png = read_png(path("n.png"));
  ASSERT_EQ(png.image.width, 24);
  ASSERT_EQ(png.image.height, 20);
  ASSERT_EQ(png.image.bit_depth, 8);
  // The view's codes are 0.5 + 0.5 · N, clamped to [0, 1], in 8 bits.
  for (std::size_t i = 0; i < n->size(); ++i) {
    const long want = std::lround(std::clamp(0.5f + 0.5f * (*n)[i], 0.0f, 1.0f) * 255.0f);
    ASSERT_EQ(png.image.samples[i / 3 * png.image.channels + i % 3], want) << "at value " << i;
  }
}

}  // namespace
}  // namespace prism
