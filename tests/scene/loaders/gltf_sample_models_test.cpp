// Khronos glTF 2.0 sample models (tests/data/gltf/, see tests/data/SOURCES.md) load with
// the structure their files declare and render under `--environment uniform`: sampler
// wrap modes (TextureSettingsTest) and a metallic-roughness texture kept linear (Suzanne).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "prism/render/renderer.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/texture_file.h"

namespace prism {
namespace {

std::filesystem::path model(const std::string& name) {
  return std::filesystem::path(PRISM_SOURCE_DIR) / "tests/data/gltf" / name / (name + ".gltf");
}

const Material& material_named(const Scene& scene, const std::string& name) {
  for (const Material& m : scene.materials)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  return scene.materials.front();
}

// Renders the scene's own camera at a small size under a uniform sky and checks the
// image is finite and lit where the model is.
void expect_renders(const Scene& loaded) {
  Scene scene = loaded;
  apply_environment_override(scene, EnvironmentOverride{"uniform", 1.0f, 0.0f});
  RenderSettings settings;
  settings.width = settings.height = 24;
  settings.samples_per_pixel = 2;
  const RenderResult result = render(scene, settings);
  double sum = 0.0;
  for (std::size_t p = 0; p < result.film.pixel_count(); ++p) {
    const Vec3d m = result.film.mean(p);
    ASSERT_TRUE(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z)) << p;
    sum += m.y;
  }
  EXPECT_GT(sum, 0.0);
}

TEST(GltfSampleModels, TextureSettingsTestMapsEachSamplersWrapModes) {
  const Scene scene = load_scene(model("TextureSettingsTest").string());
  EXPECT_EQ(scene.triangle_count(), 72u);
  EXPECT_EQ(scene.materials.size(), 10u);
  EXPECT_TRUE(scene.warnings.empty());
  // Sampler names in the file: RepeatSClampT, RepeatTClampS, RepeatSMirrorT, RepeatTMirrorS
  // (glTF S = u, T = v).
  const std::map<std::string, std::pair<TextureWrap, TextureWrap>> expected{
      {"TextureClampMaterialT", {TextureWrap::repeat, TextureWrap::clamp}},
      {"TextureClampMaterialS", {TextureWrap::clamp, TextureWrap::repeat}},
      {"TextureMirrorMaterialT", {TextureWrap::repeat, TextureWrap::mirror}},
      {"TextureMirrorMaterialS", {TextureWrap::mirror, TextureWrap::repeat}},
      {"TextureRepeatMaterialT", {TextureWrap::clamp, TextureWrap::repeat}},   // RepeatTClampS
      {"TextureRepeatMaterialS", {TextureWrap::repeat, TextureWrap::clamp}},   // RepeatSClampT
  };
  for (const auto& [name, wraps] : expected) {
    const Material& m = material_named(scene, name);
    ASSERT_GE(m.base_color_texture, 0) << name;
    const TextureImage& t = scene.textures[static_cast<std::size_t>(m.base_color_texture)];
    EXPECT_EQ(t.wrap_u, wraps.first) << name;
    EXPECT_EQ(t.wrap_v, wraps.second) << name;
  }
  expect_renders(scene);
}

TEST(GltfSampleModels, SuzanneKeepsItsMetallicRoughnessTextureLinear) {
  const Scene scene = load_scene(model("Suzanne").string());
  EXPECT_EQ(scene.triangle_count(), 3936u);
  ASSERT_EQ(scene.materials.size(), 1u);
  const Material& m = scene.materials[0];
  ASSERT_GE(m.base_color_texture, 0);
  ASSERT_GE(m.metallic_roughness_texture, 0);
  // The metallic-roughness texels are the file's codes / 255 (no sRGB decoding); the base
  // colour is decoded through the sRGB EOTF.
  const auto dir = model("Suzanne").parent_path();
  const TextureImage raw = read_texture_file(dir / "Suzanne_MetallicRoughness.png", TextureEncoding::linear, 32768);
  const TextureImage& mr = scene.textures[static_cast<std::size_t>(m.metallic_roughness_texture)];
  ASSERT_EQ(mr.sample_count(), raw.sample_count());
  EXPECT_EQ(mr.linear_values(), raw.linear_values());
  const TextureImage srgb = read_texture_file(dir / "Suzanne_BaseColor.png", TextureEncoding::srgb, 32768);
  EXPECT_EQ(scene.textures[static_cast<std::size_t>(m.base_color_texture)].linear_values(), srgb.linear_values());
  expect_renders(scene);
}

}  // namespace
}  // namespace prism
