// pbrt-v4 Shape "alpha" → Prism stochastic coverage (pbrt_alpha.cpp), and pbrt's upward v.
#include <gtest/gtest.h>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/scene/loaders/texture_png.h"

namespace prism::loaders {
namespace {

constexpr std::string_view kQuad =
    "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 1 1 0 0 1 0] \"point2 uv\" [0 0 1 0 1 1 0 1]"
    " \"integer indices\" [0 1 2 0 2 3]";

TEST(PbrtAlpha, ConstantAlphaIsBlendOpacityAndOneIsOpaque) {
  const Scene s = parse_pbrt_scene(std::string("WorldBegin\n") + std::string(kQuad) + " \"float alpha\" [0.25]\n" +
                                       std::string(kQuad) + " \"float alpha\" [1]\n",
                                   "test.pbrt", {});
  ASSERT_EQ(s.meshes.size(), 2u);
  const Material& cut = s.materials[s.meshes[0].material];
  EXPECT_EQ(cut.alpha_mode, AlphaMode::blend);
  EXPECT_FLOAT_EQ(cut.opacity, 0.25f);
  EXPECT_EQ(s.materials[s.meshes[1].material].alpha_mode, AlphaMode::opaque);
  // pbrt's v points up the image: read as 1 − v.
  EXPECT_EQ(s.meshes[0].uvs[0].y, 1.0f);
  EXPECT_EQ(s.meshes[0].uvs[2].y, 0.0f);
}

TEST(PbrtAlpha, AlphaImageBecomesTheReflectanceAlphaChannel) {
  test::ScratchFolder dir;
  // A 2×1 reflectance (red, green) and a 2×1 alpha (0, 1), written as 8-bit PNGs.
  TextureImage colour;
  colour.name = "c";
  colour.width = 2, colour.height = 1, colour.channels = 3;
  colour.texels = {1, 0, 0, 0, 1, 0};
  TextureImage alpha = colour;
  alpha.channels = 1;
  alpha.texels = {0, 1};
  write_file_atomically(dir / "c.png", encode_texture_png(colour, TextureEncoding::srgb));
  write_file_atomically(dir / "a.png", encode_texture_png(alpha, TextureEncoding::linear));
  const std::string text = std::string("WorldBegin\n") +
                           "Texture \"c\" \"spectrum\" \"imagemap\" \"string filename\" \"c.png\"\n"
                           "Texture \"a\" \"float\" \"imagemap\" \"string filename\" \"a.png\" \"string encoding\" \"linear\"\n"
                           "Material \"diffuse\" \"texture reflectance\" \"c\"\n" +
                           std::string(kQuad) + " \"texture alpha\" \"a\"\n";
  const Scene s = parse_pbrt_scene(text, "test.pbrt", dir.path());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Material& m = s.materials[s.meshes[0].material];
  EXPECT_EQ(m.alpha_mode, AlphaMode::blend);
  ASSERT_GE(m.base_color_texture, 0);
  const TextureImage& t = s.textures[static_cast<std::size_t>(m.base_color_texture)];
  ASSERT_EQ(t.channels, 4);
  const std::vector<float> expected = {1, 0, 0, 0, 0, 1, 0, 1};
  EXPECT_EQ(t.texels, expected);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  const std::string unknown = test::error_of<SceneError>(
      [&] { parse_pbrt_scene(std::string("WorldBegin\n") + std::string(kQuad) + " \"texture alpha\" \"nope\"\n", "test.pbrt", {}); });
  EXPECT_NE(unknown.find("unknown float texture 'nope'"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace prism::loaders
