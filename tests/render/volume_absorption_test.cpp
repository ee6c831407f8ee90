// Absorption inside solid glass (Beer–Lambert; glTF KHR_materials_volume, pbrt-v4 media
// inside glass): the law itself, renders through an index-matched absorbing block whose
// answer is known in closed form, the JSON rules, and the scene writers.
#include "prism/render/volume_absorption.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/scene_summary.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/scene_writers.h"
#include "scene/loaders/loader_test_files.h"
#include "support/film_statistics.h"
#include "support/write_and_reload.h"

namespace prism {
namespace {

TEST(VolumeAbsorption, LightKeepsTheAttenuationColourAfterTheAttenuationDistance) {
  color::SampledSpectrum<4> c;
  c[0] = 0.5f;
  c[1] = 0.25f;
  c[2] = 1.0f;
  c[3] = 0.0f;  // glTF allows 0: everything absorbed at once
  const color::SampledSpectrum<4> sigma = absorption_coefficient(c, 2.0f);
  const color::SampledSpectrum<4> at_d = beer_lambert_transmittance(sigma, 2.0f);
  const color::SampledSpectrum<4> at_2d = beer_lambert_transmittance(sigma, 4.0f);
  // exp and log in float: a few ulps.
  EXPECT_NEAR(at_d[0], 0.5f, 1e-6f);
  EXPECT_NEAR(at_d[1], 0.25f, 1e-6f);
  EXPECT_EQ(at_d[2], 1.0f);  // a clear channel stays exactly clear
  EXPECT_LT(at_d[3], 1e-29f);
  EXPECT_NEAR(at_2d[0], 0.25f, 1e-6f);
  EXPECT_NEAR(at_2d[1], 0.0625f, 1e-6f);
  // No length, no loss, and no NaN where σ is large.
  const color::SampledSpectrum<4> none = beer_lambert_transmittance(sigma, 0.0f);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(none[i], 1.0f) << i;
  // An infinite segment (an open mesh left from inside): absorbing channels go dark, the
  // clear one stays 1, none is a NaN.
  const color::SampledSpectrum<4> escaped = beer_lambert_transmittance(sigma, std::numeric_limits<float>::infinity());
  EXPECT_EQ(escaped[0], 0.0f);
  EXPECT_EQ(escaped[2], 1.0f);
  EXPECT_EQ(escaped[3], 0.0f);
}

// A closed box, every triangle wound counter-clockwise seen from outside (the front face
// faces out), as JSON.
std::string box_mesh(const std::string& name, const std::string& material, Vec3f lo, Vec3f hi) {
  const Vec3f corner[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                           {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const Vec3f centre = (lo + hi) * 0.5f;
  std::string positions, indices;
  for (int i = 0; i < 8; ++i)
    positions += (i ? ", [" : "[") + std::to_string(corner[i].x) + ", " + std::to_string(corner[i].y) + ", " +
                 std::to_string(corner[i].z) + "]";
  for (const auto& f : faces)
    for (const std::array<int, 3>& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      int a = t[0], b = t[1], c = t[2];
      // Outward: the triangle's normal points away from the box's centre.
      if (dot(cross(corner[b] - corner[a], corner[c] - corner[a]), corner[a] - centre) < 0.0f) std::swap(b, c);
      indices += (indices.empty() ? "" : ", ") + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c);
    }
  return R"({"name": ")" + name + R"(", "material": ")" + material + R"(", "positions": [)" + positions +
         R"(], "indices": [)" + indices + "]}";
}

// ior 1: the block's faces neither reflect nor bend, so every camera path runs straight
// through it and its weight is the block's transmittance alone.
Scene block_scene(const std::string& glass, const std::string& extra_meshes = "", const std::string& lights = "",
                  bool sky = true) {
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [)" + glass + R"(, {"name": "white", "type": "diffuse", "base_color": [0.5, 0.5, 0.5]}],
    "meshes": [)" + box_mesh("block", "glass", Vec3f(-5, -5, -4), Vec3f(5, 5, 0)) + extra_meshes + R"(],
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_degrees": 0.5})" +
                                       (sky ? R"(, "environment": {"color": [1, 1, 1], "luminance_nits": 1})" : "") +
                                       lights + "}",
                                   "block.json", {}, "block");
}

test::BlockEstimate render_mean(const Scene& scene, TransportKind kind, int max_depth = 8) {
  RenderSettings s;
  s.width = s.height = 4;
  s.samples_per_pixel = 16;
  s.transport.kind = kind;
  s.path.max_depth = max_depth;
  const Film film = render(scene, s).film;
  return test::block_estimate(film, 0, 0, film.width(), film.height());
}

const char* kAbsorbingGlass = R"({"name": "glass", "type": "dielectric", "ior": 1, "roughness": 0,
    "attenuation_color": [0.5, 0.25, 1], "attenuation_distance": 2})";

TEST(VolumeAbsorption, ABlockTransmitsItsColourToThePowerOfThicknessOverDistance) {
  // 4 units of glass at attenuation distance 2: (0.5, 0.25, 1)² per channel, of a sky of 1.
  // Within the 0.5° view the path length inside is 4 / cos θ ≤ 4 · (1 + 1e-5): the
  // transmittance moves by < 3e-5 relative; float exp/log and the film's sums add ~1e-6.
  const test::BlockEstimate e = render_mean(block_scene(kAbsorbingGlass), TransportKind::rgb);
  const double expected[3] = {0.25, 0.0625, 1.0};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], expected[c], 1e-4 * expected[c] + 1e-6) << "channel " << c;
  // The same glass with no attenuation is clear, exactly (rough, too: an index-matched
  // surface does not scatter, bsdf/dielectric.h).
  const test::BlockEstimate clear =
      render_mean(block_scene(R"({"name": "glass", "type": "dielectric", "ior": 1})"), TransportKind::rgb);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(clear.mean[c], 1.0, 1e-6) << "channel " << c;
}

TEST(VolumeAbsorption, SpectralTransportAbsorbsAGreyMediumLikeRgb) {
  // A grey attenuation colour upsamples to a flat spectrum, so every wavelength keeps
  // 0.5² = 0.25; the sky's Y of 1 carries the wavelength estimator's noise (5σ).
  const test::BlockEstimate e = render_mean(block_scene(R"({"name": "glass", "type": "dielectric", "ior": 1,
      "attenuation_color": [0.5, 0.5, 0.5], "attenuation_distance": 2})"),
                                            TransportKind::spectral);
  EXPECT_NEAR(e.mean.y, 0.25, 5.0 * std::sqrt(e.variance.y) + 1e-4);
  EXPECT_LT(e.mean.y, 0.3);
}

TEST(VolumeAbsorption, ShadowRaysInsideTheMediumAreAbsorbedToo) {
  // A grey floor 3 units deep inside the block, lit only by a point light 2 units above it,
  // also inside: the camera segment inside (3 units) and the shadow ray (2 units) both run
  // through glass of σ = ln 2 per unit, so the floor shows 2^-5 of what it shows in clear
  // glass. The same sample numbers in both renders (absorption draws none), so the ratio
  // holds per path up to the footprint of the 0.5° view on the floor: the light's distance
  // changes by < 3e-4, the ratio by < 3e-4 relative.
  const std::string floor = ", " + box_mesh("floor", "white", Vec3f(-4, -4, -3.5f), Vec3f(4, 4, -3));
  const std::string light = R"(, "lights": [{"type": "point", "position": [0, 0, -1], "intensity_cd": 10}])";
  const Scene absorbing = block_scene(R"({"name": "glass", "type": "dielectric", "ior": 1,
      "attenuation_color": [0.5, 0.5, 0.5], "attenuation_distance": 1})",
                                      floor, light, false);
  const Scene clear = block_scene(R"({"name": "glass", "type": "dielectric", "ior": 1})", floor, light, false);
  // Depth 2: the camera ray crosses the block's face (a vertex), then the floor's light
  // sample; longer paths leave through the block into the black void or stay on the floor.
  const test::BlockEstimate a = render_mean(absorbing, TransportKind::rgb, 2);
  const test::BlockEstimate b = render_mean(clear, TransportKind::rgb, 2);
  ASSERT_GT(b.mean.y, 0.0);
  EXPECT_NEAR(a.mean.y / b.mean.y, 1.0 / 32.0, 3e-4 / 32.0 + 1e-7);
}

// A checkpoint of one absorption does not resume as another (renderer.h's fingerprint).
TEST(VolumeAbsorption, TheAbsorptionIsPartOfTheImageFingerprint) {
  RenderSettings s;
  s.width = s.height = 4;
  Scene a = block_scene(kAbsorbingGlass);
  const std::uint64_t before = image_fingerprint(a, s);
  a.materials[0].attenuation_distance = 3.0f;
  EXPECT_NE(image_fingerprint(a, s), before);
  Scene b = block_scene(kAbsorbingGlass);
  b.materials[0].attenuation_color.y = 0.5f;
  EXPECT_NE(image_fingerprint(b, s), before);
}

TEST(VolumeAbsorption, JsonKeysNeedASolidDielectricAndBothValues) {
  const auto error = [](const std::string& glass) {
    return test::error_of<SceneError>([&] { block_scene(glass); });
  };
  EXPECT_NE(error(R"({"name": "glass", "type": "diffuse", "attenuation_color": [0.5, 0.5, 0.5],
      "attenuation_distance": 1})")
                .find("materials[0].attenuation_color: only dielectric materials"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "glass", "type": "dielectric", "thin_walled": true,
      "attenuation_color": [0.5, 0.5, 0.5], "attenuation_distance": 1})")
                .find("thin-walled dielectric has no inside"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "glass", "type": "dielectric", "attenuation_color": [0.5, 0.5, 0.5]})")
                .find("give 'attenuation_color' and 'attenuation_distance' together"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "glass", "type": "dielectric", "attenuation_color": [0.5, 0, 0.5],
      "attenuation_distance": 1})")
                .find("components must be in (0, 1]"),
            std::string::npos);
  EXPECT_NE(error(R"({"name": "glass", "type": "dielectric", "attenuation_color": [0.5, 0.5, 0.5],
      "attenuation_distance": 0})")
                .find("attenuation_distance: must be greater than 0"),
            std::string::npos);
  // glTF's transmission makes metallic_roughness a dielectric first, so it may absorb.
  const Scene s = block_scene(R"({"name": "glass", "type": "metallic_roughness", "transmission": 1,
      "attenuation_color": [0.5, 0.5, 0.5], "attenuation_distance": 3})");
  EXPECT_TRUE(s.materials[0].absorbs_inside());
  EXPECT_EQ(s.materials[0].attenuation_distance, 3.0f);
  // `prism info` says so, so a user sees that the attenuation was read.
  const std::string summary = format_scene_summary(s);
  EXPECT_NE(summary.find("0 emissive, 1 absorbing inside"), std::string::npos) << summary;
}

// JSON and GLB keep the colour and distance as given; pbrt-v4 has a medium inside the
// shape instead (σ_a = −ln c / d, read back as c' = exp(−σ_a) after d' = 1), so there the
// absorption coefficient is what must survive.
TEST(VolumeAbsorption, EveryWriterKeepsIt) {
  const Scene original = block_scene(kAbsorbingGlass);
  test::ScratchFolder dir;
  for (const char* name : {"block.json", "block.glb", "block.pbrt"}) {
    const std::filesystem::path path = dir / name;
    const Scene loaded = test::write_and_reload(original, path);
    const Material& m = loaded.materials[loaded.meshes[0].material];
    EXPECT_TRUE(m.absorbs_inside()) << name;
    EXPECT_EQ(m.type, MaterialType::dielectric) << name;
    EXPECT_FALSE(m.thin_walled) << name;
    if (path.extension() != ".pbrt") {
      EXPECT_EQ(m.attenuation_color, Vec3f(0.5f, 0.25f, 1.0f)) << name;
      EXPECT_EQ(m.attenuation_distance, 2.0f) << name;
    } else {
      // float log/exp and the writer's shortest round-trip decimal: a few ulps of σ.
      const Vec3f& c0 = original.materials[0].attenuation_color;
      for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(-std::log(m.attenuation_color[i]) / m.attenuation_distance,
                    -std::log(c0[i]) / original.materials[0].attenuation_distance, 1e-6)
            << name << " channel " << i;
      bool warned = false;
      for (const std::string& w : loaded.warnings) warned |= w.find("Medium") != std::string::npos;
      EXPECT_FALSE(warned);  // nothing about the medium was left unread
    }
  }
}

}  // namespace
}  // namespace prism
