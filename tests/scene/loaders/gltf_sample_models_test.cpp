// Khronos glTF 2.0 sample models (tests/data/gltf/, see tests/data/SOURCES.md) load with
// the structure their files declare and render under `--environment uniform`: sampler
// wrap modes (TextureSettingsTest), a metallic-roughness texture kept linear (Suzanne) and
// normal maps that match the geometry they were baked from (NormalTangentTest).
#include <gtest/gtest.h>

#include <algorithm>
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

// NormalTangentTest: every pair of tiles holds a hemisphere modelled in geometry (left) and
// the same hemisphere baked into the normal map of a flat tile 0.32 units to its right,
// the maps laid out in several orientations (none mirrored: mirrored uvs are
// NormalMapping.MirroredUvsMirrorTheMapsXOnly's). The mesh has no tangents, so the tangent
// frame is the renderer's own (dP/du, normal_mapping.h). Seen head-on, the first-hit normal
// AOV over each geometric bump must match the AOV at the same place on its twin.
TEST(GltfSampleModels, NormalTangentTestMapsMatchTheirGeometry) {
  Scene scene = load_scene(model("NormalTangentTest").string());
  ASSERT_EQ(scene.materials.size(), 1u);
  ASSERT_GE(scene.materials[0].normal_texture, 0);
  // 250² pixels over a 2.5 × 2.5 view of the z = 0 plane centred on the model, from 40
  // units away (nearly orthographic: a bump's top, 0.08 above the plane, lands within 0.2
  // pixels of where an orthographic view puts it): 0.01 units per pixel, so a tile's twin
  // is 32 pixels to the right.
  constexpr int kSize = 250, kTwinOffsetPixels = 32;
  constexpr float kUnitsPerPixel = 0.01f, kCentreY = -0.125f, kDistance = 40.0f;
  scene.camera.eye = {0.0f, kCentreY, kDistance};
  scene.camera.target = {0.0f, kCentreY, 0.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.fov_degrees = 2.0f * std::atan(0.5f * kSize * kUnitsPerPixel / kDistance) * 180.0f / 3.14159265f;
  apply_environment_override(scene, EnvironmentOverride{"uniform", 1.0f, 0.0f});
  RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.samples_per_pixel = 4;
  settings.path.max_depth = 1;  // the AOV is the first hit's; no need for more bounces
  settings.aovs.normal = true;
  const RenderResult result = render(scene, settings);
  const auto normal = [&](int x, int y) {
    const Vec3d n = result.film.normal_mean(static_cast<std::size_t>(y) * kSize + static_cast<std::size_t>(x));
    return n / std::sqrt(dot(n, n));
  };
  // The geometric bumps' centres (the mesh's highest vertices): three columns, five rows.
  double worst_mean_degrees = 0.0, sum_degrees = 0.0;
  int compared = 0;
  for (const float cx : {-0.96f, -0.16f, 0.64f})
    for (const float cy : {0.8029f, 0.4170f, 0.0f, -0.4170f, -0.8029f}) {
      double bump_degrees = 0.0;
      int bump_pixels = 0;
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x + kTwinOffsetPixels < kSize; ++x) {
          // Pixel centres within 0.07 of the bump's centre: on the hemisphere (radius
          // 0.092), clear of its rim, where the slope turns steep and the map's baked
          // normals of a smooth sphere part from the low-poly mesh's facets.
          const float wx = (x + 0.5f - 0.5f * kSize) * kUnitsPerPixel;
          const float wy = kCentreY - (y + 0.5f - 0.5f * kSize) * kUnitsPerPixel;
          if ((wx - cx) * (wx - cx) + (wy - cy) * (wy - cy) > 0.07f * 0.07f) continue;
          const Vec3d geometric = normal(x, y), mapped = normal(x + kTwinOffsetPixels, y);
          ASSERT_GT(geometric.z, 0.3) << x << " " << y;  // the bump, facing the camera
          const double degrees = std::acos(std::clamp(dot(geometric, mapped), -1.0, 1.0)) * 180.0 / 3.14159265358979;
          bump_degrees += degrees;
          ++bump_pixels;
        }
      ASSERT_GT(bump_pixels, 100) << cx << " " << cy;
      worst_mean_degrees = std::max(worst_mean_degrees, bump_degrees / bump_pixels);
      sum_degrees += bump_degrees;
      compared += bump_pixels;
    }
  // Measured: 0.94° over the 2334 pixels compared, 1.52° for the worst bump; what remains
  // is the bake of a smooth sphere against the low-poly mesh, and 8-bit codes. A bitangent
  // of the wrong sign (a flipped green channel) gives 36.6° (37.5° worst), a tangent of
  // the wrong sign 37.2° (39.1°): the bounds sit well between the two.
  EXPECT_LT(sum_degrees / compared, 5.0);
  EXPECT_LT(worst_mean_degrees, 8.0);
}

}  // namespace
}  // namespace prism
