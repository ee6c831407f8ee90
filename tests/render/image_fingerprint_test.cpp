// The image fingerprint (render/image_fingerprint.h) tells apart renders whose pixels
// differ, and only those.
//
// A field added to a scene or settings struct that changes pixels must be hashed, or a
// checkpoint of the old scene would resume into the new one. The compiler cannot list a
// struct's fields, so the structs' sizes stand in for them: when one grows or shrinks,
// FingerprintCoversEveryField fails until someone has looked at render/image_fingerprint.cpp
// (hash the new field where it changes pixels; say why not where it does not, e.g. names
// and exposure settings) and updated the size here. The sizes are those of x86-64 Linux
// with libstdc++, the platform CI builds on; elsewhere the check is skipped.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "prism/render/image_fingerprint.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"

namespace prism {
namespace {

TEST(ImageFingerprint, FingerprintCoversEveryField) {
#if defined(__x86_64__) && defined(__GLIBCXX__)
  const char* review = " changed size: review render/image_fingerprint.cpp for the new field, then update this test";
  EXPECT_EQ(sizeof(Material), 448u) << "Material" << review;
  EXPECT_EQ(sizeof(Emission), 88u) << "Emission" << review;
  EXPECT_EQ(sizeof(Light), 208u) << "Light" << review;
  EXPECT_EQ(sizeof(Camera), 96u) << "Camera" << review;
  EXPECT_EQ(sizeof(TriangleMesh), 184u) << "TriangleMesh" << review;
  EXPECT_EQ(sizeof(Instance), 52u) << "Instance" << review;
  EXPECT_EQ(sizeof(TextureImage), 216u) << "TextureImage" << review;
  EXPECT_EQ(sizeof(PathSettings), 24u) << "PathSettings" << review;
  EXPECT_EQ(sizeof(TransportSettings), 56u) << "TransportSettings" << review;
  EXPECT_EQ(sizeof(LightSamplerOptions), 2u) << "LightSamplerOptions" << review;
#else
  GTEST_SKIP() << "struct sizes are recorded for x86-64 libstdc++ only";
#endif
}

RenderSettings small_settings() {
  RenderSettings s;
  s.width = s.height = 16;
  s.samples_per_pixel = 4;
  return s;
}

// Each change that alters pixels alters the fingerprint.
TEST(ImageFingerprint, EveryPixelChangingEditChangesIt) {
  const Scene base = make_cornell_box();
  const std::uint64_t reference = image_fingerprint(base, small_settings());
  const std::vector<std::pair<std::string, std::function<void(Scene&, RenderSettings&)>>> edits = {
      {"base colour", [](Scene& s, RenderSettings&) { s.materials[0].base_color.x += 0.1f; }},
      {"roughness", [](Scene& s, RenderSettings&) { s.materials[0].roughness += 0.1f; }},
      {"emission", [](Scene& s, RenderSettings&) { s.materials.back().emission.luminance_nits += 1.0f; }},
      {"sheen", [](Scene& s, RenderSettings&) { s.materials[0].sheen_color = Vec3f(0.5f); }},
      {"clear coat", [](Scene& s, RenderSettings&) { s.materials[0].clearcoat = 0.5f; }},
      {"vertex", [](Scene& s, RenderSettings&) { s.meshes[0].positions[0].x += 0.01f; }},
      {"camera", [](Scene& s, RenderSettings&) { s.camera.fov_degrees += 1.0f; }},
      {"seed", [](Scene&, RenderSettings& r) { r.seed = 7; }},
      {"bounces", [](Scene&, RenderSettings& r) { r.path.max_depth += 1; }},
      {"sampler", [](Scene&, RenderSettings& r) { r.path.sampler = SamplerKind::independent; }},
      {"transport", [](Scene&, RenderSettings& r) { r.transport.kind = TransportKind::rgb; }},
      {"wavelengths", [](Scene&, RenderSettings& r) { r.transport.wavelengths = 8; }},
      {"integrator", [](Scene&, RenderSettings& r) { r.integrator = IntegratorKind::reference; }},
      {"size", [](Scene&, RenderSettings& r) { r.width = 17; }},
  };
  for (const auto& [what, edit] : edits) {
    Scene scene = base;
    RenderSettings settings = small_settings();
    edit(scene, settings);
    EXPECT_NE(image_fingerprint(scene, settings), reference) << what;
  }
}

// What does not change pixels leaves it alone: partial renders of one image merge.
TEST(ImageFingerprint, SettingsThatKeepPixelsKeepIt) {
  const Scene scene = make_cornell_box();
  const std::uint64_t reference = image_fingerprint(scene, small_settings());
  RenderSettings s = small_settings();
  s.samples_per_pixel = 1024;
  s.first_sample = 3;
  s.threads = 1;
  s.time_limit_seconds = 5.0;
  s.path.simd = SimdLevel::scalar;
  EXPECT_EQ(image_fingerprint(scene, s), reference);
  Scene renamed = scene;
  renamed.materials[0].name = "another name";
  EXPECT_EQ(image_fingerprint(renamed, small_settings()), reference);
}

}  // namespace
}  // namespace prism
