#include "prism/scene/loaders/pbrt_scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "prism/io/png.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/emission.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/spectral_inputs.h"

namespace prism::loaders {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(PRISM_SOURCE_DIR) / "data/scenes";

Scene parse_pbrt_text(std::string_view text, const std::filesystem::path& dir = {}) {
  return parse_pbrt_scene(text, "test.pbrt", dir);
}

std::string pbrt_parse_error(std::string_view text, const std::filesystem::path& dir = {}) {
  return test::error_of<SceneError>([&] { parse_pbrt_text(text, dir); });
}

constexpr std::string_view kTriangle =
    "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n";

TEST(PbrtLoader, CornellBoxMatchesBuiltIn) {
  const Scene pbrt = load_scene((kScenes / "cornell-box.pbrt").string());
  const Scene builtin = make_builtin_scene("cornell-box");
  EXPECT_EQ(pbrt.triangle_count(), builtin.triangle_count());
  EXPECT_NEAR(length(pbrt.camera.eye - builtin.camera.eye), 0.0f, 1e-3f);
  EXPECT_NEAR(length(normalize(pbrt.camera.target - pbrt.camera.eye) - normalize(builtin.camera.target - builtin.camera.eye)), 0.0f, 1e-5f);
  EXPECT_NEAR(length(pbrt.camera.up - builtin.camera.up), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(pbrt.camera.fov_degrees, builtin.camera.fov_degrees);
  EXPECT_EQ(pbrt.default_width, 512);
  EXPECT_EQ(pbrt.default_height, 512);
  EXPECT_EQ(pbrt.default_spp, 64);
  EXPECT_EQ(pbrt.default_max_depth, 8);
  // Every built-in reflectance appears in the pbrt scene, and the one emitter matches.
  for (const Material& b : builtin.materials) {
    bool found = false;
    for (const Material& p : pbrt.materials)
      found |= p.type == MaterialType::diffuse && p.base_color == b.base_color && p.is_emissive() == b.is_emissive();
    EXPECT_TRUE(found) << b.name;
  }
  int emitters = 0;
  for (const Material& m : pbrt.materials)
    if (m.is_emissive()) {
      ++emitters;
      EXPECT_EQ(m.emission.color, Vec3f(17.0f, 12.0f, 4.0f));
      EXPECT_FLOAT_EQ(m.emission.luminance_nits, builtin.materials[3].emission.luminance_nits);
      EXPECT_FALSE(m.emission.two_sided);
    }
  EXPECT_EQ(emitters, 1);
  // The light's triangles face down, as the built-in's.
  for (const TriangleMesh& mesh : pbrt.meshes)
    if (pbrt.materials[mesh.material].is_emissive()) {
      const Vec3f& a = mesh.positions[mesh.indices[0]];
      const Vec3f n = cross(mesh.positions[mesh.indices[1]] - a, mesh.positions[mesh.indices[2]] - a);
      EXPECT_LT(n.y, 0.0f);
    }
  for (const auto& w : pbrt.warnings) EXPECT_EQ(w.find("mirrored"), std::string::npos) << w;
}

TEST(PbrtLoader, GlossyVariantMapsMaterials) {
  const Scene s = load_scene((kScenes / "cornell-box-glossy.pbrt").string());
  int gold = 0, glass = 0, aluminium = 0;
  for (const Material& m : s.materials) {
    if (m.type == MaterialType::conductor && m.conductor_name == "Au") {
      ++gold;
      EXPECT_EQ(m.conductor_fresnel, ConductorFresnel::complex_ior);
      EXPECT_NEAR(m.roughness, std::sqrt(0.1f), 1e-6f);  // α = sqrt(0.01) = 0.1, r = sqrt(α)
    }
    if (m.type == MaterialType::conductor && m.conductor_name == "Al") {
      ++aluminium;
      EXPECT_NEAR(m.roughness, std::sqrt(0.2f), 1e-6f);  // no remap: α = 0.2
    }
    if (m.type == MaterialType::dielectric) {
      ++glass;
      EXPECT_EQ(m.dispersion, DispersionModel::sellmeier);
      EXPECT_NEAR(m.ior, 1.5168f, 1e-3f);
    }
  }
  EXPECT_EQ(gold, 1);
  EXPECT_EQ(glass, 1);
  EXPECT_EQ(aluminium, 1);
}

TEST(PbrtLoader, TransformsInstancesAndNamedMaterials) {
  const Scene s = parse_pbrt_text(std::string(R"(
WorldBegin
MakeNamedMaterial "m" "string type" "diffuse" "rgb reflectance" [0.2 0.3 0.4]
ObjectBegin "tri"
  NamedMaterial "m"
)") + std::string(kTriangle) + R"(
ObjectEnd
AttributeBegin
  Translate 10 0 0
  ObjectInstance "tri"
AttributeEnd
AttributeBegin
  Rotate 90 0 0 1
  Scale 2 2 2
  ObjectInstance "tri"
AttributeEnd
ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  0 0 5 1]
)" + std::string(kTriangle));
  ASSERT_EQ(s.meshes.size(), 2u);
  ASSERT_EQ(s.instances.size(), 3u);  // the world triangle + two placements
  EXPECT_EQ(s.meshes[1].positions[1], Vec3f(1, 0, 5));  // the world mesh, transform baked in
  EXPECT_EQ(s.instances[0].mesh, 1u);
  EXPECT_EQ(s.instances[1].object_to_world.apply_point(Vec3f(1, 0, 0)), Vec3f(11, 0, 0));
  const Vec3f r = s.instances[2].object_to_world.apply_point(Vec3f(1, 0, 0));
  EXPECT_NEAR(r.x, 0.0f, 1e-5f);
  EXPECT_NEAR(r.y, 2.0f, 1e-5f);
  EXPECT_EQ(s.materials[s.meshes[0].material].base_color, Vec3f(0.2f, 0.3f, 0.4f));
}

TEST(PbrtLoader, MaterialMappings) {
  const auto material_of = [](std::string_view decl) {
    const Scene s = parse_pbrt_text("WorldBegin\n" + std::string(decl) + "\n" + std::string(kTriangle));
    return std::make_pair(s.materials[s.meshes[0].material], s.warnings);
  };
  auto [schlick, w1] = material_of(R"(Material "conductor" "rgb reflectance" [0.9 0.8 0.7] "float roughness" 0.25 "bool remaproughness" false)");
  EXPECT_EQ(schlick.conductor_fresnel, ConductorFresnel::schlick);
  EXPECT_EQ(schlick.base_color, Vec3f(0.9f, 0.8f, 0.7f));
  EXPECT_FLOAT_EQ(schlick.roughness, 0.5f);
  auto [copper, w2] = material_of(R"(Material "conductor")");
  EXPECT_EQ(copper.conductor_name, "Cu");
  EXPECT_FLOAT_EQ(copper.roughness, 0.0f);
  // pbrt-v4's maxdepth 0 is emitted light only, which Prism renders as such (not depth 1).
  EXPECT_EQ(parse_pbrt_text("Integrator \"path\" \"integer maxdepth\" 0\nWorldBegin\n" + std::string(kTriangle)).default_max_depth, 0);
  EXPECT_FALSE(pbrt_parse_error("Integrator \"path\" \"integer maxdepth\" -1\nWorldBegin\n" + std::string(kTriangle)).empty());
  auto [glass, w3] = material_of(R"(Material "dielectric" "float eta" 1.33)");
  EXPECT_EQ(glass.type, MaterialType::dielectric);
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  EXPECT_EQ(glass.dispersion, DispersionModel::none);
  auto [coated, w4] = material_of(R"(Material "coateddiffuse" "rgb reflectance" [0.5 0.1 0.1] "float roughness" 0.1)");
  EXPECT_EQ(coated.type, MaterialType::diffuse);
  ASSERT_EQ(w4.size(), 1u);
  EXPECT_NE(w4[0].find("coateddiffuse"), std::string::npos);
  auto [bb, w5] = material_of(R"(Material "diffuse" "blackbody reflectance" 6500)");
  EXPECT_GT(bb.base_color.x, 0.0f);
  EXPECT_NE(w5[0].find("blackbody"), std::string::npos);
}

// pbrt-v4's "string normalmap" on any material: an RGB image read as linear.
TEST(PbrtLoader, NormalMapIsALinearRgbImage) {
  test::ScratchFolder dir;
  write_png(dir / "normal.png", EncodedImage{1, 1, 3, 8, {128, 64, 255}});
  write_png(dir / "grey.png", EncodedImage{1, 1, 1, 8, {128}});
  const std::string conductor = "WorldBegin\nMaterial \"conductor\" \"string normalmap\" \"normal.png\"\n";
  const auto scene = dir.write("scene.pbrt", conductor + std::string(kTriangle));
  const Scene s = load_pbrt_scene(scene);
  const Material& m = s.materials[s.meshes[0].material];
  ASSERT_GE(m.normal_texture, 0);
  EXPECT_FLOAT_EQ(s.textures[static_cast<std::size_t>(m.normal_texture)].value(1), 64.0f / 255.0f);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("normalmap"), std::string::npos) << w;
  const auto grey = dir.write(
      "grey.pbrt", "WorldBegin\n\nMaterial \"diffuse\" \"string normalmap\" \"grey.png\"\n" + std::string(kTriangle));
  const std::string message = test::error_of<SceneError>([&] { load_pbrt_scene(grey); });
  EXPECT_NE(message.find("grey.pbrt:3"), std::string::npos) << message;
  EXPECT_NE(message.find("RGB"), std::string::npos) << message;
}

// The images are decoded together at the end of the file (texture_cache.h), but a bad one
// is still reported as one-at-a-time decoding would: the first in the file, with its line,
// before any error the parser met after it.
TEST(PbrtLoader, TheFirstBadImageIsReportedWithItsLine) {
  test::ScratchFolder dir;
  write_png(dir / "good.png", EncodedImage{1, 1, 3, 8, {128, 64, 255}});
  dir.write("bad.png", "\x89PNG\r\n\x1a\n truncated");
  dir.write("worse.png", "not an image");
  const std::string textures = "WorldBegin\n"
                               "Texture \"a\" \"spectrum\" \"imagemap\" \"string filename\" \"good.png\"\n"
                               "Texture \"b\" \"spectrum\" \"imagemap\" \"string filename\" \"bad.png\"\n"
                               "Texture \"c\" \"spectrum\" \"imagemap\" \"string filename\" \"worse.png\"\n";
  for (const std::string& tail : {std::string(kTriangle), std::string("Shape \"nonsense\" [\n")}) {
    const std::string message =
        test::error_of<IoError>([&] { load_pbrt_scene(dir.write("scene.pbrt", textures + tail)); });
    EXPECT_EQ(message.rfind("scene.pbrt:3: Texture: cannot read image", 0), 0u) << message;
    EXPECT_NE(message.find("bad.png"), std::string::npos) << message;
  }
  // With good images the parser's own error stands.
  const std::string message = test::error_of<SceneError>([&] {
    load_pbrt_scene(dir.write("scene.pbrt", "WorldBegin\nTexture \"a\" \"spectrum\" \"imagemap\" "
                                            "\"string filename\" \"good.png\"\nShape \"nonsense\" [\n"));
  });
  EXPECT_NE(message.find("scene.pbrt:3"), std::string::npos) << message;
}

// "bool invert": pbrt-v4 inverts the scaled value, max(0, 1 − scale · v), on colour
// channels. The texture becomes a float copy with the scale baked in (tint 1).
TEST(PbrtLoader, InvertedImageMapsAreApplied) {
  test::ScratchFolder dir;
  write_png(dir / "g.png", EncodedImage{1, 1, 1, 8, {128}});
  write_png(dir / "rgba.png", EncodedImage{1, 1, 4, 8, {255, 0, 128, 64}});
  const auto load = [&](const std::string& file, std::string_view params) {
    const std::string text = "WorldBegin\nTexture \"g\" \"spectrum\" \"imagemap\" \"string filename\" \"" + file +
                             "\" \"string encoding\" \"linear\" " + std::string(params) +
                             "\nMaterial \"diffuse\" \"texture reflectance\" \"g\"\n";
    return load_pbrt_scene(dir.write("scene.pbrt", text + std::string(kTriangle)));
  };
  const float v = 128.0f / 255.0f;
  const Scene inverted = load("g.png", "\"bool invert\" true \"float scale\" 1.5");
  const Material& m = inverted.materials[inverted.meshes[0].material];
  ASSERT_GE(m.base_color_texture, 0);
  const TextureImage& t = inverted.textures[static_cast<std::size_t>(m.base_color_texture)];
  EXPECT_FLOAT_EQ(t.value(0), 1.0f - 1.5f * v);
  EXPECT_EQ(m.base_color, Vec3f(1.0f));  // the scale is in the texels now
  for (const std::string& w : inverted.warnings) EXPECT_EQ(w.find("invert"), std::string::npos) << w;
  // Clamped at 0 where the scaled value passes 1; alpha is not inverted.
  const Scene rgba = load("rgba.png", "\"bool invert\" true");
  const TextureImage& c = rgba.textures[static_cast<std::size_t>(rgba.materials[rgba.meshes[0].material].base_color_texture)];
  EXPECT_EQ(c.value(0), 0.0f);
  EXPECT_EQ(c.value(1), 1.0f);
  EXPECT_FLOAT_EQ(c.value(2), 1.0f - v);
  EXPECT_FLOAT_EQ(c.value(3), 64.0f / 255.0f);
  // Without invert, the image keeps its codes and the scale stays a tint.
  const Scene plain = load("g.png", "\"bool invert\" false \"float scale\" 1.5");
  const Material& p = plain.materials[plain.meshes[0].material];
  EXPECT_TRUE(plain.textures[static_cast<std::size_t>(p.base_color_texture)].has_codes());
  EXPECT_EQ(p.base_color, Vec3f(1.5f));
}

// Textured roughness (pbrt-v4's float textures): a copy of the image holding Prism's
// perceptual r per texel (r = sqrt(α), α = sqrt(v) with remaproughness, α = v without) in
// the G channel the renderer reads, B = 1; the material's factor is 1. A constant float
// texture is a number; two different u/v textures are an approximation, said.
TEST(PbrtLoader, TexturedRoughnessIsBakedIntoPrismsRoughness) {
  test::ScratchFolder dir;
  write_png(dir / "r.png", EncodedImage{2, 1, 1, 8, {64, 255}});
  const std::string textures = "WorldBegin\n"
                               "Texture \"r\" \"float\" \"imagemap\" \"string filename\" \"r.png\" "
                               "\"string encoding\" \"linear\" \"float scale\" 0.5\n"
                               "Texture \"c\" \"float\" \"constant\" \"float value\" 0.0625\n";
  const auto load = [&](const std::string& material) {
    return load_pbrt_scene(dir.write("scene.pbrt", textures + material + "\n" + std::string(kTriangle)));
  };
  const float v0 = 0.5f * 64.0f / 255.0f, v1 = 0.5f;
  const Scene remapped = load(R"(Material "conductor" "texture roughness" "r")");
  const Material& m = remapped.materials[remapped.meshes[0].material];
  EXPECT_EQ(m.roughness, 1.0f);
  ASSERT_GE(m.metallic_roughness_texture, 0);
  const TextureImage& t = remapped.textures[static_cast<std::size_t>(m.metallic_roughness_texture)];
  ASSERT_EQ(t.channels, 3);
  EXPECT_FLOAT_EQ(t.value(1), std::pow(v0, 0.25f));  // texel 0, G: r = α^½ = v^¼
  EXPECT_EQ(t.value(2), 1.0f);                       // B: metallic kept
  EXPECT_FLOAT_EQ(t.value(4), std::pow(v1, 0.25f));  // texel 1
  const Scene linear = load(R"(Material "dielectric" "texture roughness" "r" "bool remaproughness" false)");
  const Material& g = linear.materials[linear.meshes[0].material];
  ASSERT_GE(g.metallic_roughness_texture, 0);
  EXPECT_FLOAT_EQ(linear.textures[static_cast<std::size_t>(g.metallic_roughness_texture)].value(1), std::sqrt(v0));
  // The coat's roughness of a coated material goes to its own texture.
  const Scene coated = load(R"(Material "coateddiffuse" "texture roughness" "r")");
  const Material& c = coated.materials[coated.meshes[0].material];
  EXPECT_EQ(c.metallic_roughness_texture, -1);
  ASSERT_GE(c.clearcoat_roughness_texture, 0);
  EXPECT_EQ(c.clearcoat_roughness, 1.0f);
  const Scene constant = load(R"(Material "conductor" "texture roughness" "c")");
  const Material& k = constant.materials[constant.meshes[0].material];
  EXPECT_EQ(k.metallic_roughness_texture, -1);
  EXPECT_FLOAT_EQ(k.roughness, 0.5f);  // α = sqrt(0.0625) = 0.25, r = 0.5
  const Scene anisotropic = load(R"(Material "conductor" "texture uroughness" "r" "float vroughness" 0.1)");
  bool said = false;
  for (const std::string& w : anisotropic.warnings) said |= w.find("anisotropic roughness as its uroughness texture") != std::string::npos;
  EXPECT_TRUE(said);
  const std::string message = test::error_of<SceneError>([&] { load(R"(Material "conductor" "texture roughness" "nope")"); });
  EXPECT_NE(message.find("unknown float texture 'nope'"), std::string::npos) << message;
}

// A material's "texture displacement" (a float texture) is a bump map: the image, with the
// texture's "scale" as the bump scale; a constant "float displacement" bends nothing.
TEST(PbrtLoader, DisplacementIsABumpMap) {
  test::ScratchFolder dir;
  write_png(dir / "height.png", EncodedImage{1, 1, 1, 8, {128}});
  const std::string text = "WorldBegin\n"
                           "Texture \"h\" \"float\" \"imagemap\" \"string filename\" \"height.png\" "
                           "\"string encoding\" \"linear\" \"float scale\" 0.05\n"
                           "Material \"diffuse\" \"texture displacement\" \"h\"\n";
  const Scene s = load_pbrt_scene(dir.write("scene.pbrt", text + std::string(kTriangle)));
  const Material& m = s.materials[s.meshes[0].material];
  ASSERT_GE(m.bump_texture, 0);
  EXPECT_FLOAT_EQ(m.bump_scale, 0.05f);
  EXPECT_FLOAT_EQ(s.textures[static_cast<std::size_t>(m.bump_texture)].value(0), 128.0f / 255.0f);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("displacement"), std::string::npos) << w;
  const std::string flat = "WorldBegin\nMaterial \"diffuse\" \"float displacement\" 0.1\n";
  const Scene constant = parse_pbrt_text(flat + std::string(kTriangle));
  EXPECT_EQ(constant.materials[constant.meshes[0].material].bump_texture, -1);
  for (const std::string& w : constant.warnings) EXPECT_EQ(w.find("displacement"), std::string::npos) << w;
  EXPECT_NE(pbrt_parse_error("WorldBegin\n\nMaterial \"diffuse\" \"texture displacement\" \"nope\"\n").find(":3:"),
            std::string::npos);
}

// pbrt-v4 multiplies "scale" by a distant light's "illuminance" (the spectrum normalised to
// unit luminance first), as it does for every photometric quantity.
TEST(PbrtLoader, DistantIlluminanceIsTimesScale) {
  const Scene s = parse_pbrt_text(std::string(R"(WorldBegin
LightSource "distant" "rgb L" [0.3 0.6 0.9] "float scale" 2 "float illuminance" 1000
)") + std::string(kTriangle));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 2000.0f);
}

TEST(PbrtLoader, LightsInPhotometricUnits) {
  const Scene s = parse_pbrt_text(std::string(R"(
WorldBegin
LightSource "point" "rgb I" [1 1 1] "float scale" 10 "point3 from" [0 5 0]
LightSource "point" "float power" 100
LightSource "spot" "point3 from" [0 0 0] "point3 to" [0 -1 0] "float coneangle" 40 "float conedelta" 10
LightSource "distant" "point3 from" [0 1 0] "point3 to" [0 0 0] "float illuminance" 1000
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [2 2 2] "bool twosided" true
)") + std::string(kTriangle) + "AttributeEnd\n" +
                        R"(AttributeBegin
  AreaLightSource "diffuse" "float power" 3.14159265
)" + std::string(kTriangle) + "AttributeEnd\n");
  ASSERT_EQ(s.lights.size(), 5u);
  EXPECT_EQ(s.lights[0].type, LightType::point);
  EXPECT_NEAR(s.lights[0].intensity, 10.0f, 1e-4f);
  EXPECT_EQ(s.lights[0].position, Vec3f(0, 5, 0));
  EXPECT_NEAR(s.lights[1].intensity, 100.0 / (4.0 * 3.14159265), 1e-3);
  EXPECT_EQ(s.lights[2].type, LightType::spot);
  EXPECT_FLOAT_EQ(s.lights[2].spot_outer_angle_degrees, 40.0f);
  EXPECT_FLOAT_EQ(s.lights[2].spot_inner_angle_degrees, 30.0f);
  EXPECT_EQ(s.lights[2].direction, Vec3f(0, -1, 0));
  EXPECT_EQ(s.lights[3].type, LightType::directional);
  EXPECT_FLOAT_EQ(s.lights[3].intensity, 1000.0f);
  EXPECT_EQ(s.lights[3].direction, Vec3f(0, -1, 0));
  EXPECT_EQ(s.lights[4].type, LightType::environment);
  EXPECT_NEAR(s.lights[4].intensity, 0.5f, 1e-4f);
  const Material& two_sided = s.materials[s.meshes[0].material];
  EXPECT_TRUE(two_sided.emission.two_sided);
  EXPECT_NEAR(two_sided.emission.luminance_nits, 2.0f, 1e-4f);
  // power π on a triangle of area 1/2, one side: L = Φ / (π A) = 2.
  EXPECT_NEAR(s.materials[s.meshes[1].material].emission.luminance_nits, 2.0f, 1e-4f);
}

// pbrt-v4 multiplies the intensity or radiance that `power` sets by `scale` (its
// PointLight, SpotLight and DiffuseAreaLight ::Create), and ignores a power of 0.
TEST(PbrtLoader, ScaleMultipliesWhatPowerSets) {
  const Scene s = parse_pbrt_text(std::string(R"(
WorldBegin
LightSource "point" "float power" 100 "float scale" 2
LightSource "spot" "point3 from" [0 0 0] "point3 to" [0 -1 0] "float coneangle" 40 "float conedelta" 10 "float power" 10 "float scale" 3
LightSource "point" "float power" 0 "float scale" 4
AttributeBegin
  AreaLightSource "diffuse" "float power" 3.14159265 "float scale" 2
)") + std::string(kTriangle) + "AttributeEnd\n");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_NEAR(s.lights[0].intensity, 2.0 * 100.0 / (4.0 * 3.14159265), 1e-3);
  // Spot: Φ over 2π (1 − (cos 30° + cos 40°)/2), times 3.
  const double spot_solid_angle = 2.0 * 3.14159265 * (1.0 - 0.5 * (std::cos(30.0 * 3.14159265 / 180.0) +
                                                                  std::cos(40.0 * 3.14159265 / 180.0)));
  EXPECT_NEAR(s.lights[1].intensity, 3.0 * 10.0 / spot_solid_angle, 1e-3);
  EXPECT_NEAR(s.lights[2].intensity, 4.0, 1e-4);  // power 0: the light as given, I = 1 × scale
  // power π on a triangle of area 1/2, one side: L = Φ / (π A) = 2, times 2.
  EXPECT_NEAR(s.materials[s.meshes[0].material].emission.luminance_nits, 4.0f, 1e-4f);
}

// Light spectra pbrt-v4 can name or tabulate are rendered as data (scene/spectral_inputs.h),
// normalised to unit luminance times `scale` as pbrt-v4 does; so are sampled reflectances
// within [0, 1]. Other named spectra keep their RGB approximation (and its warning).
TEST(PbrtLoader, SpectraBecomeSceneSpectra) {
  const Scene s = parse_pbrt_text(std::string(R"(
WorldBegin
LightSource "point" "blackbody I" 2856 "float scale" 7 "point3 from" [0 5 0]
LightSource "distant" "spectrum L" "stdillum-F11" "point3 from" [0 1 0] "point3 to" [0 0 0]
LightSource "spot" "spectrum I" [400 1 500 2 600 3 700 4] "point3 from" [0 0 0] "point3 to" [0 -1 0]
LightSource "infinite" "blackbody L" 6500
LightSource "point" "spectrum I" "stdillum-F3.1"
Material "diffuse" "spectrum reflectance" [400 0.1 700 0.9]
AttributeBegin
  AreaLightSource "diffuse" "spectrum L" "stdillum-A" "float scale" 3
)") + std::string(kTriangle) + "AttributeEnd\n" + R"(Material "diffuse" "spectrum reflectance" [400 0.5 700 1.5]
)" + std::string(kTriangle));
  ASSERT_EQ(s.lights.size(), 5u);
  ASSERT_TRUE(s.lights[0].spectrum);
  EXPECT_EQ(*s.lights[0].spectrum, blackbody_emission_spectrum(2856.0));
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 7.0f);
  EXPECT_EQ(s.lights[0].color, emission_spectrum_srgb(*s.lights[0].spectrum));
  ASSERT_TRUE(s.lights[1].spectrum);
  EXPECT_EQ(*s.lights[1].spectrum, *named_emission_spectrum("F11"));
  ASSERT_TRUE(s.lights[2].spectrum);
  EXPECT_DOUBLE_EQ((*s.lights[2].spectrum)(550.0), 2.5);
  ASSERT_TRUE(s.lights[3].spectrum);  // a constant sky's spectrum too
  EXPECT_EQ(*s.lights[3].spectrum, blackbody_emission_spectrum(6500.0));
  EXPECT_FALSE(s.lights[4].spectrum);  // FL3.1 is not one of Prism's tables
  const Material& lamp = s.materials[s.meshes[0].material];
  ASSERT_TRUE(lamp.emission.spectrum);
  EXPECT_EQ(*lamp.emission.spectrum, *named_emission_spectrum("A"));
  EXPECT_FLOAT_EQ(lamp.emission.luminance_nits, 3.0f);
  ASSERT_TRUE(lamp.base_color_spectrum);
  EXPECT_DOUBLE_EQ((*lamp.base_color_spectrum)(550.0), 0.5);
  EXPECT_FALSE(s.materials[s.meshes[1].material].base_color_spectrum);  // above 1: not a reflectance
  std::string warnings;
  for (const std::string& w : s.warnings) warnings += w + "\n";
  EXPECT_EQ(warnings.find("blackbody I"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("line 3"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("stdillum-F3.1"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("6500"), std::string::npos) << warnings;
}

// A sampled spectrum breaking the scene-data rules (spectrum_table_checks.h) is an error at
// its line, with the same message as in a JSON scene.
TEST(PbrtLoader, MalformedSampledSpectraAreErrorsAtTheirLine) {
  const std::string decreasing =
      pbrt_parse_error("WorldBegin\nMaterial \"diffuse\" \"spectrum reflectance\" [500 0.1 400 0.9]\n");
  EXPECT_NE(decreasing.find("wavelengths must increase: 400 nm follows 500 nm"), std::string::npos) << decreasing;
  EXPECT_NE(decreasing.find("test.pbrt:2: parameter 'reflectance'"), std::string::npos) << decreasing;
  const std::string micrometres = pbrt_parse_error("WorldBegin\nLightSource \"point\" \"spectrum I\" [0.4 1 0.7 1]\n");
  EXPECT_NE(micrometres.find("wavelength 0.4 nm is outside [100, 3000] nm"), std::string::npos) << micrometres;
  const std::string negative = pbrt_parse_error("WorldBegin\nLightSource \"point\" \"spectrum I\" [400 1 700 -1]\n");
  EXPECT_NE(negative.find("negative value -1 at 700 nm"), std::string::npos) << negative;
}

TEST(PbrtLoader, ShapesSphereBilinearAndPly) {
  test::ScratchFolder dir;
  dir.write("quad.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const Scene s = parse_pbrt_text(R"(
WorldBegin
Shape "sphere" "float radius" 2
Shape "bilinearmesh" "point3 P" [0 0 0 1 0 0 0 1 0 1 1 0]
Shape "plymesh" "string filename" "quad.ply"
)",
                        dir.path());
  ASSERT_EQ(s.meshes.size(), 3u);
  for (const Vec3f& p : s.meshes[0].positions) EXPECT_NEAR(length(p), 2.0f, 1e-4f);
  EXPECT_EQ(s.meshes[1].triangle_count(), 2u);
  const auto& b = s.meshes[1];
  const Vec3f n = cross(b.positions[b.indices[1]] - b.positions[b.indices[0]], b.positions[b.indices[2]] - b.positions[b.indices[0]]);
  EXPECT_GT(n.z, 0.0f);  // (p10 − p00) × (p01 − p00) = +z
  EXPECT_EQ(s.meshes[2].triangle_count(), 2u);
  EXPECT_NE(pbrt_parse_error(R"(WorldBegin Shape "plymesh" "string filename" "../quad.ply")", dir.path()).find("test.pbrt:1"),
            std::string::npos);
}

TEST(PbrtLoader, IncludeResolvesInsideTheFolderOnly) {
  test::ScratchFolder dir;
  dir.write("geometry/tri.pbrt", kTriangle);
  const auto scene = dir.write("scene.pbrt", "WorldBegin\nInclude \"geometry/tri.pbrt\"\nImport \"geometry/tri.pbrt\"\n");
  EXPECT_EQ(load_pbrt_scene(scene).meshes.size(), 2u);
  const auto escape = dir.write("escape.pbrt", "WorldBegin\nInclude \"/etc/passwd\"\n");
  EXPECT_NE(test::error_of<SceneError>([&] { load_pbrt_scene(escape); }).find("escape.pbrt:2"), std::string::npos);
  const auto self = dir.write("self.pbrt", "Include \"self.pbrt\"\n");
  EXPECT_NE(test::error_of<SceneError>([&] { load_pbrt_scene(self); }).find("nested more than"), std::string::npos);
  const auto missing = dir.write("missing.pbrt", "WorldBegin\n\nInclude \"nope.pbrt\"\n");
  EXPECT_NE(test::error_of<IoError>([&] { load_pbrt_scene(missing); }).find("missing.pbrt:3: Include"), std::string::npos);
  const auto no_ply = dir.write("noply.pbrt", "WorldBegin\nShape \"plymesh\" \"string filename\" \"nope.ply\"\n");
  EXPECT_NE(test::error_of<IoError>([&] { load_pbrt_scene(no_ply); }).find("noply.pbrt:2: plymesh"), std::string::npos);
  dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\n");
  const auto bad_ply = dir.write("badply.pbrt", "WorldBegin\nShape \"plymesh\" \"string filename\" \"bad.ply\"\n");
  EXPECT_NE(test::error_of<SceneError>([&] { load_pbrt_scene(bad_ply); }).find("badply.pbrt:2: plymesh: bad.ply:"), std::string::npos);
  const auto no_tex = dir.write("notex.pbrt", "WorldBegin\nTexture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"nope.png\"\n");
  EXPECT_NE(test::error_of<IoError>([&] { load_pbrt_scene(no_tex); }).find("notex.pbrt:2: Texture"), std::string::npos);
  const auto bad = dir.write("geometry/bad.pbrt", "\n\nShape \"trianglemesh\" \"point3 P\" [0 0]\n");
  const auto outer = dir.write("outer.pbrt", "Include \"geometry/bad.pbrt\"\n");
  EXPECT_NE(test::error_of<SceneError>([&] { load_pbrt_scene(outer); }).find("bad.pbrt:3:"), std::string::npos);
}

TEST(PbrtLoader, UnsupportedFeaturesInOneWarning) {
  const Scene s = parse_pbrt_text(std::string(R"(
Option "bool disablepixeljitter" true
PixelFilter "gaussian"
Sampler "halton" "integer pixelsamples" 8 "string randomization" "owen"
WorldBegin
MakeNamedMedium "fog" "string type" "homogeneous"
LightSource "goniometric" "string filename" "x.exr"
Shape "curve" "point3 P" [0 0 0 1 1 1 2 2 2 3 3 3]
Material "hair"
)") + std::string(kTriangle));
  int ignored = 0;
  for (const auto& w : s.warnings)
    if (w.find("ignored") != std::string::npos) {
      ++ignored;
      for (const char* what : {"PixelFilter (line 3)", "randomization",
                               "MakeNamedMedium \"fog\": a scattering medium (sigma_s > 0); media are rendered only as "
                               "absorption inside glass (line 6)",
                               "goniometric",
                               "curve", "hair", "Option"})
        EXPECT_NE(w.find(what), std::string::npos) << what << " in " << w;
    }
  EXPECT_EQ(ignored, 1);
  EXPECT_EQ(s.default_spp, 8);
}

// A medium that only absorbs, inside solid glass, is the glass's Beer–Lambert absorption
// (pbrt_media.cpp): σ_a × scale per unit becomes the colour exp(−σ) after one unit. The
// rest of media is warned, and names are checked.
TEST(PbrtLoader, AbsorbingMediumInsideGlass) {
  const Scene s = parse_pbrt_text(std::string(R"(WorldBegin
MakeNamedMedium "ink" "string type" "homogeneous" "rgb sigma_a" [0.5 1 0] "rgb sigma_s" [0 0 0] "float scale" 2
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [1 1 1]
Material "dielectric" "float eta" 1.33
AttributeBegin
  MediumInterface "ink" ""
)") + std::string(kTriangle) + R"(AttributeEnd
AttributeBegin
  MediumInterface "fog" ""
)" + std::string(kTriangle) + R"(AttributeEnd
AttributeBegin
  Material "diffuse"
  MediumInterface "ink" ""
)" + std::string(kTriangle) + R"(AttributeEnd
)" + std::string(kTriangle));
  ASSERT_EQ(s.meshes.size(), 4u);
  const Material& ink = s.materials[s.meshes[0].material];
  EXPECT_EQ(ink.type, MaterialType::dielectric);
  EXPECT_TRUE(ink.absorbs_inside());
  EXPECT_EQ(ink.attenuation_distance, 1.0f);
  EXPECT_FLOAT_EQ(ink.attenuation_color.x, std::exp(-1.0f));
  EXPECT_FLOAT_EQ(ink.attenuation_color.y, std::exp(-2.0f));
  EXPECT_EQ(ink.attenuation_color.z, 1.0f);
  // A scattering medium (σ_s defaults to 1) is not rendered: clear glass, and a warning.
  EXPECT_FALSE(s.materials[s.meshes[1].material].absorbs_inside());
  // Outside any AttributeBegin with a MediumInterface, the glass has no medium.
  EXPECT_FALSE(s.materials[s.meshes[3].material].absorbs_inside());
  EXPECT_EQ(s.materials[s.meshes[3].material].type, MaterialType::dielectric);
  ASSERT_FALSE(s.warnings.empty());
  std::string warnings;
  for (const std::string& w : s.warnings) warnings += w + "\n";
  EXPECT_NE(warnings.find("MakeNamedMedium \"fog\": a scattering medium"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("MediumInterface interior \"ink\" on a shape that is not solid glass"), std::string::npos)
      << warnings;
  EXPECT_EQ(warnings.find("\"ink\": a"), std::string::npos) << warnings;  // the ink itself is rendered
  // Media around shapes (exterior) are not rendered either: said.
  const Scene around = parse_pbrt_text(std::string(R"(MakeNamedMedium "air" "string type" "homogeneous" "rgb sigma_s" [0 0 0]
WorldBegin
MediumInterface "" "air"
)") + std::string(kTriangle));
  ASSERT_EQ(around.warnings.size(), 1u);
  EXPECT_NE(around.warnings[0].find("MediumInterface exterior medium \"air\""), std::string::npos) << around.warnings[0];
  // Names must be defined, once.
  EXPECT_NE(pbrt_parse_error("MediumInterface \"nope\" \"\"").find("test.pbrt:1: medium \"nope\" is not defined"),
            std::string::npos);
  EXPECT_NE(pbrt_parse_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n"
                        "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"")
                .find("test.pbrt:2: medium \"m\" is defined twice"),
            std::string::npos);
  EXPECT_NE(pbrt_parse_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [1 -1 1]")
                .find("test.pbrt:1:"),
            std::string::npos);
}

TEST(PbrtLoader, BadInputIsAFileLineError) {
  const std::pair<std::string_view, std::string_view> cases[] = {
      {"WorldBegin\n\"oops\"", "test.pbrt:2: expected a directive"},
      {"Frobnicate 1 2", "test.pbrt:1: unknown directive 'Frobnicate'"},
      {"\nLookAt 0 0 0 0 0 0 0 1 0", "test.pbrt:2: LookAt"},
      {"Translate 1 2", "test.pbrt:1: Translate expects 3 numbers"},
      {"Translate 1 2 x", "test.pbrt:1: expected a number"},
      {"Camera \"perspective\" \"float fov\" [ 1 2", "unterminated '['"},
      {"Camera \"perspective\" \"float fov\" 200", "test.pbrt:1: parameter 'fov'"},
      {"Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 5]", "out of range"},
      {"Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1]", "multiple of 3"},
      {"Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 -1]", "out of range"},
      {"Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2.5]", "out of range"},
      {"Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 1e999]", "expected a number"},
      {"AttributeEnd", "without a matching begin"},
      {"AttributeBegin", "without AttributeEnd"},
      {"NamedMaterial \"nope\"", "unknown named material"},
      {"ObjectInstance \"nope\"", "unknown object"},
      {"Shape \"trianglemesh\" \"P\" [0]", "expected a parameter declaration"},
      {"Shape \"x\" \"string s\" [1]", "needs string values"},
      {"Material \"diffuse\" \"rgb reflectance\" [1 -1 1]", "must not be negative"},
      {"Material \"diffuse\" \"texture reflectance\" \"nope\"", "unknown texture"},
      {"Shape \"plymesh\" \"string filename\" \"a.ply\"", "test.pbrt:1: filename"},
      {"\"unterminated", "unterminated string"},
      {"WorldBegin WorldBegin", "a second WorldBegin"},
      {"Scale 0 0 0\nShape \"sphere\"", "test.pbrt:2: Shape: the transform is singular"},
      {"MakeNamedMaterial \"x\" \"rgb reflectance\" [1 1 1]", "has no \"string type\""},
      {"Texture \"t\" \"spectrum\" \"imagemap\"", "needs a filename"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = pbrt_parse_error(text);
    EXPECT_NE(message.find(expected), std::string::npos) << text << " → " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace prism::loaders
