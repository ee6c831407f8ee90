// End-to-end: `prism render --denoise` writes the denoised beauty with the noisy one and the
// guides as layers; `prism denoise` gives the same image from that file, reads pbrt-v4's
// layer names, and refuses a file without the guides (one line, exit 1, no output).
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "prism/io/exr.h"
#include "support/cli_test.h"

namespace prism {
namespace {
namespace fs = std::filesystem;

class DenoiseCli : public test::CliTest {};

std::set<std::string> exr_channel_names(const std::string& file) {
  Imf::InputFile in(file.c_str());
  std::set<std::string> names;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) names.insert(it.name());
  return names;
}

const std::string kDenoiseRender = "render cornell-box --width 32 --height 24 --seed 4 --spp 8 ";

TEST_F(DenoiseCli, RenderWritesDenoisedBeautyAndNoisyLayer) {
  ASSERT_EQ(run(kDenoiseRender + "--denoise -o " + path("d.exr") + " -o " + path("d.png")), 0) << log();
  ASSERT_EQ(run(kDenoiseRender + "--aov albedo,normal,depth,variance -o " + path("n.exr")), 0) << log();
  EXPECT_EQ(exr_channel_names(path("d.exr")),
            (std::set<std::string>{"R", "G", "B", "noisy.R", "noisy.G", "noisy.B", "albedo.R", "albedo.G", "albedo.B",
                                   "N.x", "N.y", "N.z", "Z", "Z.coverage", "variance.R", "variance.G",
                                   "variance.B"}));
  EXPECT_TRUE(fs::exists(path("d.png")));
  const ExrFile noisy = read_exr(path("n.exr"));
  const auto noisy_layer = read_exr_channels(path("d.exr"), {"noisy.R", "noisy.G", "noisy.B"});
  ASSERT_TRUE(noisy_layer);
  EXPECT_EQ(*noisy_layer, noisy.image.rgb) << "noisy.* is not the plain render's beauty";
  const ExrFile denoised = read_exr(path("d.exr"));
  EXPECT_NE(denoised.image.rgb, noisy.image.rgb) << "--denoise left the beauty as it was";

  // `prism denoise` on the plain render with the same AOVs reproduces the render's result.
  ASSERT_EQ(run("denoise " + path("n.exr") + " -o " + path("again.exr") + " --threads 1"), 0) << log();
  EXPECT_EQ(read_exr(path("again.exr")).image.rgb, denoised.image.rgb);
  EXPECT_EQ(*read_exr_channels(path("again.exr"), {"noisy.R", "noisy.G", "noisy.B"}), noisy.image.rgb);
}

TEST_F(DenoiseCli, ReadsPbrtV4LayerNames) {
  // A file with pbrt-v4 GBufferFilm's names: Albedo.*, Ns.*, P.* (camera-space position)
  // and Variance.* (the samples' variance, with samplesPerPixel).
  ASSERT_EQ(run(kDenoiseRender + "--aov albedo,normal,depth,variance -o " + path("n.exr")), 0) << log();
  const ExrFile prism_file = read_exr(path("n.exr"));
  const auto albedo = *read_exr_channels(path("n.exr"), {"albedo.R", "albedo.G", "albedo.B"});
  const auto normal = *read_exr_channels(path("n.exr"), {"N.x", "N.y", "N.z"});
  const auto depth = *read_exr_channels(path("n.exr"), {"Z"});
  auto variance = *read_exr_channels(path("n.exr"), {"variance.R", "variance.G", "variance.B"});
  std::vector<float> position(3 * depth.size(), 0.0f);
  for (std::size_t i = 0; i < depth.size(); ++i) position[3 * i + 2] = std::isfinite(depth[i]) ? depth[i] : 0.0f;
  for (float& v : variance) v *= 8.0f;  // pbrt-v4 stores s², the mean's variance times spp
  ExrMetadata meta;
  meta.ints["samplesPerPixel"] = 8;
  write_exr(path("pbrt.exr"), prism_file.image, prism_file.chromaticities, meta, {},
            {{{"Albedo.R", "Albedo.G", "Albedo.B"}, albedo},
             {{"Ns.X", "Ns.Y", "Ns.Z"}, normal},
             {{"P.X", "P.Y", "P.Z"}, position},
             {{"Variance.R", "Variance.G", "Variance.B"}, variance}});
  ASSERT_EQ(run("denoise " + path("pbrt.exr") + " -o " + path("pbrt_d.exr")), 0) << log();
  ASSERT_EQ(run("denoise " + path("n.exr") + " -o " + path("prism_d.exr")), 0) << log();
  const auto a = read_exr(path("pbrt_d.exr")).image.rgb, b = read_exr(path("prism_d.exr")).image.rgb;
  ASSERT_EQ(a.size(), b.size());
  // Same guides up to float rounding of s²·8/8 and of |P|: the images agree closely.
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-4f * std::max(1.0f, b[i])) << i;
}

TEST_F(DenoiseCli, RefusesFileWithoutGuides) {
  ASSERT_EQ(run(kDenoiseRender + "--aov albedo,normal -o " + path("partial.exr")), 0) << log();
  EXPECT_EQ(run("denoise " + path("partial.exr") + " -o " + path("out.exr")), 1);
  const std::string message = log();
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  EXPECT_NE(message.find("prism: error: "), std::string::npos) << message;
  EXPECT_NE(message.find("depth (Z"), std::string::npos) << message;
  EXPECT_NE(message.find("variance (variance.R/G/B"), std::string::npos) << message;
  EXPECT_EQ(message.find("albedo ("), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(path("out.exr")));
  EXPECT_EQ(run("denoise " + path("missing.exr") + " -o " + path("out.exr")), 1) << log();
  EXPECT_FALSE(fs::exists(path("out.exr")));
  EXPECT_EQ(run("denoise " + path("partial.exr") + " -o " + path("out.png")), 2) << log();
}

}  // namespace
}  // namespace prism
