// glTF 2.0 loader tests on documents generated here (no model files from ../shared).
#include "prism/scene/loaders/gltf_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "prism/core/memory_budget.h"
#include "prism/io/png.h"
#include "prism/scene/emission.h"
#include "prism/scene/load_scene.h"

namespace prism::loaders {
namespace {

using test::append;
using test::glb;

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], k[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += {k[v >> 18], k[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], '='};
  }
  return out;
}

// A unit quad in the xy plane: positions (48 B), uvs (32 B), ushort indices (12 B).
std::string quad_buffer() {
  std::string b;
  append<float>(b, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  append<float>(b, {0, 1, 1, 1, 1, 0, 0, 0});
  append<std::uint16_t>(b, {0, 1, 2, 0, 2, 3});
  return b;
}

// The JSON of a document around quad_buffer(); `buffer_uri` empty: GLB's binary chunk.
std::string quad_document(const std::string& buffer_uri, const std::string& extra_top = "",
                          const std::string& materials = R"([{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1], "metallicFactor": 0.3, "roughnessFactor": 0.6}}])") {
  const std::string uri = buffer_uri.empty() ? "" : R"("uri": ")" + buffer_uri + R"(", )";
  return R"({"asset": {"version": "2.0"}, )" + extra_top + R"(
  "buffers": [{)" + uri + R"("byteLength": 92}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
  "materials": )" + materials + R"(,
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "aspectRatio": 2.0, "znear": 0.1}}],
  "nodes": [{"mesh": 0, "translation": [10, 0, 0]},
            {"children": [2], "rotation": [0, 0, 0.7071068, 0.7071068]},
            {"mesh": 0, "scale": [2, 2, 2]},
            {"camera": 0, "translation": [0, 0, 5]}],
  "scenes": [{"nodes": [0, 1, 3]}]
})";
}

Scene parse_gltf_text(const std::string& text, const std::filesystem::path& dir = {}, LoadOptions options = {}) {
  return parse_gltf_scene({reinterpret_cast<const unsigned char*>(text.data()), text.size()}, "test.gltf", dir, options);
}

std::string gltf_parse_error(const std::string& text, const std::filesystem::path& dir = {}) {
  return test::error_of<SceneError>([&] { parse_gltf_text(text, dir); });
}

const std::string kDataUri = "data:application/octet-stream;base64,";

TEST(GltfLoader, NodeHierarchyInstancesAndCamera) {
  const Scene s = parse_gltf_text(quad_document(kDataUri + base64(quad_buffer())));
  ASSERT_EQ(s.meshes.size(), 1u);  // one mesh, shared
  ASSERT_EQ(s.instances.size(), 2u);
  EXPECT_EQ(s.meshes[0].triangle_count(), 2u);
  EXPECT_EQ(s.meshes[0].uvs.size(), 4u);
  EXPECT_EQ(s.instances[0].object_to_world.apply_point(Vec3f(1, 0, 0)), Vec3f(11, 0, 0));
  const Vec3f p = s.instances[1].object_to_world.apply_point(Vec3f(1, 0, 0));  // scale 2, then 90° about z
  EXPECT_NEAR(p.x, 0.0f, 1e-5f);
  EXPECT_NEAR(p.y, 2.0f, 1e-5f);
  EXPECT_EQ(s.camera.eye, Vec3f(0, 0, 5));
  EXPECT_EQ(s.camera.target, Vec3f(0, 0, 4));
  EXPECT_NEAR(s.camera.fov_degrees, 0.5 * 180.0 / std::numbers::pi, 1e-4);  // landscape: vertical is shorter
  EXPECT_EQ(s.default_width, 1024);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.type, MaterialType::metallic_roughness);
  EXPECT_EQ(m.base_color, Vec3f(0.5f, 0.25f, 1.0f));
  EXPECT_FLOAT_EQ(m.metallic, 0.3f);
  EXPECT_FLOAT_EQ(m.roughness, 0.6f);
}

TEST(GltfLoader, BinaryGlbAndExternalBuffer) {
  const Scene s = parse_gltf_text(glb(quad_document(""), quad_buffer()));
  EXPECT_EQ(s.instances.size(), 2u);
  test::ScratchFolder dir;
  dir.write("quad.bin", quad_buffer());
  const auto file = dir.write("quad.gltf", quad_document("quad.bin"));
  EXPECT_EQ(load_scene(file.string()).meshes.size(), 1u);
}

TEST(GltfLoader, UriEscapingTheFolderIsRefused) {
  test::ScratchFolder dir;
  dir.write("outside.bin", quad_buffer());
  std::filesystem::create_directories(dir / "scene");
  for (const std::string& uri : std::vector<std::string>{"../outside.bin", "..%2Foutside.bin"}) {
    const std::string message = gltf_parse_error(quad_document(uri), dir / "scene");
    EXPECT_NE(message.find("outside the scene's folder"), std::string::npos) << uri << ": " << message;
  }
  const std::string absolute = (dir / "outside.bin").string();
  EXPECT_EQ(gltf_parse_error(quad_document(absolute), dir / "scene"),
            "test.gltf: buffer or image uri: absolute path '" + absolute +
                "' refused (scene files may only refer to files in their own folder; use --allow-external-paths to "
                "permit it)");
  EXPECT_EQ(gltf_parse_error(quad_document("../outside.bin"), dir / "scene"),
            "test.gltf: buffer or image uri: path '../outside.bin' leads outside the scene's folder (refused; use "
            "--allow-external-paths to permit it)");
  // A scene without a folder (read from memory) refers to no file at all.
  EXPECT_NE(gltf_parse_error(quad_document("quad.bin")).find("cannot refer to the file 'quad.bin'"), std::string::npos);
  LoadOptions allow;
  allow.allow_external_paths = true;
  EXPECT_EQ(parse_gltf_text(quad_document("../outside.bin"), dir / "scene", allow).meshes.size(), 1u);
  EXPECT_EQ(parse_gltf_text(quad_document(absolute), dir / "scene", allow).meshes.size(), 1u);
}

// A buffer the scene's folder lacks is looked for nowhere else (tinygltf would try the
// process's working folder next).
TEST(GltfLoader, UriIsNotLookedForInTheWorkingFolder) {
  test::ScratchFolder dir;
  std::filesystem::create_directories(dir / "scene");
  dir.write("quad.bin", quad_buffer());
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  const std::string message = gltf_parse_error(quad_document("quad.bin"), dir / "scene");
  std::filesystem::current_path(previous);
  EXPECT_NE(message.find("File not found : quad.bin"), std::string::npos) << message;
}

std::string with_asset(const std::string& asset) {
  std::string doc = quad_document(kDataUri + base64(quad_buffer()));
  const std::string original = R"("asset": {"version": "2.0"})";
  return doc.replace(doc.find(original), original.size(), R"("asset": )" + asset);
}

// glTF 2.0 §3.2: minVersion, when given, must be supported; otherwise version's major.
TEST(GltfLoader, OnlyGltfTwoIsRead) {
  EXPECT_EQ(parse_gltf_text(with_asset(R"({"version": "2.1"})")).instances.size(), 2u);  // minor versions add, compatibly
  EXPECT_EQ(parse_gltf_text(with_asset(R"({"version": "3.0", "minVersion": "2.0"})")).instances.size(), 2u);
  EXPECT_EQ(gltf_parse_error(with_asset(R"({"version": "7.0"})")),
            "test.gltf: glTF version 7.0 (asset.version) is not supported; Prism reads glTF 2.0");
  EXPECT_EQ(gltf_parse_error(with_asset(R"({"version": "1.0"})")),
            "test.gltf: glTF version 1.0 (asset.version) is not supported; Prism reads glTF 2.0");
  EXPECT_EQ(gltf_parse_error(with_asset(R"({"version": "2.1", "minVersion": "2.1"})")),
            "test.gltf: the file needs glTF 2.1 (asset.minVersion); Prism reads glTF 2.0");
  EXPECT_EQ(gltf_parse_error(with_asset(R"({"version": "two"})")),
            "test.gltf: asset.version 'two' is not a glTF version (MAJOR.MINOR); Prism reads glTF 2.0");
  EXPECT_EQ(gltf_parse_error(with_asset(R"({"version": "2."})")),
            "test.gltf: asset.version '2.' is not a glTF version (MAJOR.MINOR); Prism reads glTF 2.0");
  // The version is reported even where the rest of the file does not read as glTF 2.0.
  EXPECT_EQ(gltf_parse_error(R"({"asset": {"version": "7.0"}, "buffers": [{"byteLength": "many"}]})"),
            "test.gltf: glTF version 7.0 (asset.version) is not supported; Prism reads glTF 2.0");
}

TEST(GltfLoader, MaterialsExtensionsAndLights) {
  test::ScratchFolder dir;
  EncodedImage png;
  png.width = png.height = 2;
  png.channels = 4;
  png.bit_depth = 8;
  png.samples = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 0};
  write_png(dir / "albedo.png", png);
  dir.write("quad.bin", quad_buffer());
  const std::string materials = R"([
    {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "scale": [2, 2], "rotation": 0.25}}}},
     "alphaMode": "MASK", "alphaCutoff": 0.3,
     "emissiveFactor": [1, 0.5, 0.25], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 10}}},
    {"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.45}}}])";
  const std::string top = R"("extensionsUsed": ["KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_transmission",
       "KHR_materials_ior", "KHR_lights_punctual", "EXT_fancy_thing"],
    "extensionsRequired": ["KHR_texture_transform"],
    "textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": 33071, "wrapT": 33648}], "images": [{"uri": "albedo.png"}],
    "extensions": {"KHR_lights_punctual": {"lights": [
      {"type": "point", "intensity": 100, "color": [1, 0.5, 0.5]},
      {"type": "spot", "intensity": 50, "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.5}},
      {"type": "directional", "intensity": 1000}]}},)";
  std::string doc = quad_document("quad.bin", top, materials);
  const std::string nodes_end = R"({"camera": 0, "translation": [0, 0, 5]}])";
  doc.replace(doc.find(nodes_end), nodes_end.size(),
              R"({"camera": 0, "translation": [0, 0, 5]}, {"translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}},
                 {"extensions": {"KHR_lights_punctual": {"light": 1}}}, {"extensions": {"KHR_lights_punctual": {"light": 2}}}])");
  doc.replace(doc.find(R"("nodes": [0, 1, 3])"), 18, R"("nodes": [0, 1, 3, 4, 5, 6])");
  const Scene s = parse_gltf_text(doc, dir.path());
  const Material& textured = s.materials[0];
  ASSERT_GE(textured.base_color_texture, 0);
  const TextureImage& t = s.textures[textured.base_color_texture];
  EXPECT_EQ(t.width, 2);
  EXPECT_FLOAT_EQ(t.offset_u, 0.5f);
  EXPECT_FLOAT_EQ(t.scale_v, 2.0f);
  EXPECT_FLOAT_EQ(t.rotation_radians, 0.25f);
  EXPECT_EQ(t.wrap_u, TextureWrap::clamp);
  EXPECT_EQ(t.wrap_v, TextureWrap::mirror);
  EXPECT_EQ(textured.alpha_mode, AlphaMode::mask);
  EXPECT_FLOAT_EQ(textured.alpha_cutoff, 0.3f);
  EXPECT_NEAR(textured.emission.luminance_nits, 10.0 * relative_luminance(Vec3f(1, 0.5f, 0.25f), ColorPickerSpace::srgb), 1e-4);
  const Material& glass = s.materials[1];
  EXPECT_EQ(glass.type, MaterialType::dielectric);
  EXPECT_FLOAT_EQ(glass.ior, 1.45f);
  EXPECT_TRUE(glass.thin_walled);
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightType::point);
  // KHR_lights_punctual: color × intensity, so the luminous intensity is 100 × Y(color).
  EXPECT_NEAR(s.lights[0].intensity, 100.0 * relative_luminance(Vec3f(1, 0.5f, 0.5f), ColorPickerSpace::srgb), 1e-4);
  EXPECT_EQ(s.lights[0].position, Vec3f(1, 2, 3));
  EXPECT_EQ(s.lights[1].type, LightType::spot);
  EXPECT_NEAR(s.lights[1].spot_outer_angle_degrees, 0.5 * 180.0 / std::numbers::pi, 1e-4);
  EXPECT_EQ(s.lights[1].direction, Vec3f(0, 0, -1));
  EXPECT_EQ(s.lights[2].type, LightType::directional);
  EXPECT_FLOAT_EQ(s.lights[2].intensity, 1000.0f);
  int extension_warnings = 0;
  for (const auto& w : s.warnings) extension_warnings += w.find("EXT_fancy_thing") != std::string::npos;
  EXPECT_EQ(extension_warnings, 1);
}

// normalTexture (glTF 2.0 §3.9.3): the image read as linear data, even where the same
// image is also a base colour (sRGB) texture, and its scale kept; a grey image cannot hold
// a tangent-space normal and is dropped with a warning.
TEST(GltfLoader, NormalTextureIsLinearDataWithItsScale) {
  test::ScratchFolder dir;
  write_png(dir / "normal.png", EncodedImage{1, 1, 3, 8, {128, 64, 255}});
  write_png(dir / "grey.png", EncodedImage{1, 1, 1, 8, {128}});
  dir.write("quad.bin", quad_buffer());
  const std::string materials = R"([
    {"normalTexture": {"index": 0, "scale": 0.5}, "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
    {"normalTexture": {"index": 1}}])";
  const std::string top =
      R"("textures": [{"source": 0}, {"source": 1}], "images": [{"uri": "normal.png"}, {"uri": "grey.png"}],)";
  const Scene s = parse_gltf_text(quad_document("quad.bin", top, materials), dir.path());
  const Material& mapped = s.materials[0];
  ASSERT_GE(mapped.normal_texture, 0);
  EXPECT_NE(mapped.normal_texture, mapped.base_color_texture);
  EXPECT_FLOAT_EQ(mapped.normal_scale, 0.5f);
  const TextureImage& normal = s.textures[static_cast<std::size_t>(mapped.normal_texture)];
  EXPECT_FLOAT_EQ(normal.value(0), 128.0f / 255.0f);  // linear: no sRGB decoding
  EXPECT_FLOAT_EQ(normal.value(1), 64.0f / 255.0f);
  EXPECT_LT(s.textures[static_cast<std::size_t>(mapped.base_color_texture)].value(0), 0.25f);  // sRGB 128 ≈ 0.216
  EXPECT_EQ(s.materials[1].normal_texture, -1);
  EXPECT_FLOAT_EQ(s.materials[1].normal_scale, 1.0f);
  bool warned = false;
  for (const std::string& w : s.warnings) warned |= w.find("materials[1].normalTexture") != std::string::npos;
  EXPECT_TRUE(warned);
}

// Three materials with an image each (a 64×64 RGB PNG of its own pattern), the first
// image also used as the third material's normal map (so it is decoded twice, sRGB and
// linear).
std::string three_textured_materials(test::ScratchFolder& dir) {
  for (int i = 0; i < 3; ++i) {
    EncodedImage png{64, 64, 3, 8, {}};
    for (int p = 0; p < 64 * 64 * 3; ++p) png.samples.push_back(static_cast<std::uint16_t>((p * (i + 3)) % 256));
    write_png(dir / ("t" + std::to_string(i) + ".png"), png);
  }
  dir.write("quad.bin", quad_buffer());
  const std::string materials = R"([
    {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
    {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicRoughnessTexture": {"index": 2}}},
    {"normalTexture": {"index": 0}, "emissiveTexture": {"index": 2}, "emissiveFactor": [1, 1, 1]}])";
  const std::string top = R"("textures": [{"source": 0}, {"source": 1}, {"source": 2}],
    "images": [{"uri": "t0.png"}, {"uri": "t1.png"}, {"uri": "t2.png"}],)";
  return quad_document("quad.bin", top, materials);
}

// The materials' images are decoded together, ahead of the materials, when their texels
// and decoder buffers all fit in the memory budget at once; otherwise one at a time, as
// they are met. Either way the scene is the same: the same textures in the same order.
TEST(GltfLoader, ImagesDecodedTogetherOrOneAtATimeGiveTheSameScene) {
  test::ScratchFolder dir;
  const std::string doc = three_textured_materials(dir);
  // Five decodes of 64 × 64 × 3 samples: 12 KiB of codes kept, and the decoder's 12 KiB
  // buffer while it decodes.
  constexpr std::uint64_t kTexels = 64 * 64 * 3, kCodes = 64 * 64 * 3;
  MemoryBudget roomy(5 * (kTexels + kCodes));  // all at once fits: decoded together
  MemoryBudget tight(5 * kTexels + kCodes);    // only one buffer at a time fits: one by one
  const Scene together = parse_gltf_text(doc, dir.path(), LoadOptions{.memory_budget = &roomy});
  const Scene one_by_one = parse_gltf_text(doc, dir.path(), LoadOptions{.memory_budget = &tight});
  EXPECT_EQ(roomy.used_bytes(), 5 * kTexels);
  EXPECT_EQ(tight.used_bytes(), 5 * kTexels);
  ASSERT_EQ(together.textures.size(), 5u);
  ASSERT_EQ(one_by_one.textures.size(), 5u);
  for (std::size_t t = 0; t < 5; ++t) {
    EXPECT_EQ(together.textures[t].name, one_by_one.textures[t].name) << t;
    EXPECT_EQ(together.textures[t].linear_values(), one_by_one.textures[t].linear_values()) << t;
  }
  for (std::size_t m = 0; m < 3; ++m) {
    EXPECT_EQ(together.materials[m].base_color_texture, one_by_one.materials[m].base_color_texture);
    EXPECT_EQ(together.materials[m].normal_texture, one_by_one.materials[m].normal_texture);
    EXPECT_EQ(together.materials[m].emission.texture, one_by_one.materials[m].emission.texture);
  }
  // Image 0 as colour (sRGB) and as the normal map (linear): two textures.
  EXPECT_NE(together.textures[static_cast<std::size_t>(together.materials[0].base_color_texture)].linear_values(),
            together.textures[static_cast<std::size_t>(together.materials[2].normal_texture)].linear_values());
  // Too small for one at a time as well: the error names the first image that does not fit.
  MemoryBudget too_small(3 * kTexels + kCodes);
  const std::string message =
      test::error_of<Error>([&] { parse_gltf_text(doc, dir.path(), LoadOptions{.memory_budget = &too_small}); });
  EXPECT_NE(message.find("t2.png"), std::string::npos) << message;  // the 4th decode: t2 as metal-roughness
}

// Decoded together, errors are still those of decoding one image after another: the first
// bad image in the materials' order, every time.
TEST(GltfLoader, ImageErrorsComeInTheMaterialsOrder) {
  test::ScratchFolder dir;
  const std::string doc = three_textured_materials(dir);
  dir.write("t1.png", "\x89PNG\r\n\x1a\n truncated");
  dir.write("t2.png", "not an image at all");
  for (int run = 0; run < 8; ++run) {
    const std::string message = test::error_of<IoError>([&] { parse_gltf_text(doc, dir.path()); });
    EXPECT_NE(message.find("t1.png"), std::string::npos) << message;
  }
}

// KHR_materials_volume: a volume with a thickness bounds absorbing glass; its default
// thicknessFactor of 0 means thin-walled (the extension's text), as does no volume at all.
TEST(GltfLoader, VolumeThicknessAndAttenuation) {
  const auto glass = [](const std::string& volume) {
    return R"({"extensions": {"KHR_materials_transmission": {"transmissionFactor": 1})" +
           (volume.empty() ? std::string() : R"(, "KHR_materials_volume": )" + volume) + "}}";
  };
  const std::string materials = "[" + glass("") + ", " + glass("{}") + ", " +
                                glass(R"({"thicknessFactor": 0.2})") + ", " +
                                glass(R"({"thicknessFactor": 1, "attenuationColor": [0.5, 0.25, 1], "attenuationDistance": 2})") +
                                ", " + glass(R"({"attenuationColor": [0.5, 0.5, 0.5], "attenuationDistance": 1})") + "]";
  const Scene s = parse_gltf_text(quad_document(kDataUri + base64(quad_buffer()), "", materials));
  ASSERT_EQ(s.materials.size(), 5u);
  EXPECT_TRUE(s.materials[0].thin_walled);
  EXPECT_TRUE(s.materials[1].thin_walled);  // thicknessFactor defaults to 0
  EXPECT_FALSE(s.materials[2].thin_walled);
  EXPECT_FALSE(s.materials[2].absorbs_inside());  // attenuationDistance defaults to +∞
  const Material& absorbing = s.materials[3];
  EXPECT_FALSE(absorbing.thin_walled);
  EXPECT_TRUE(absorbing.absorbs_inside());
  EXPECT_EQ(absorbing.attenuation_color, Vec3f(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(absorbing.attenuation_distance, 2.0f);
  // Attenuation on a thin-walled volume has no inside to act in: said, not silently dropped.
  EXPECT_TRUE(s.materials[4].thin_walled);
  EXPECT_FALSE(s.materials[4].absorbs_inside());
  int warned = 0;
  for (const std::string& w : s.warnings)
    warned += w.find("materials[4].extensions.KHR_materials_volume: attenuation ignored") != std::string::npos;
  EXPECT_EQ(warned, 1);
  for (const auto& [volume, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"({"thicknessFactor": 1, "attenuationDistance": 0})", "attenuationDistance must be > 0"},
           {R"({"thicknessFactor": 1, "attenuationColor": [2, 0, 0], "attenuationDistance": 1})",
            "attenuationColor components must be in [0, 1]"},
           {R"({"thicknessFactor": 1, "attenuationColor": [1, 0], "attenuationDistance": 1})",
            "attenuationColor must be an array of three numbers"},
           {R"({"thicknessFactor": -1})", "thicknessFactor must be"}}) {
    const std::string message = gltf_parse_error(quad_document(kDataUri + base64(quad_buffer()), "", "[" + glass(volume) + "]"));
    EXPECT_NE(message.find(expected), std::string::npos) << volume << " → " << message;
    EXPECT_NE(message.find("KHR_materials_volume"), std::string::npos) << message;
  }
}

// KHR_materials_clearcoat: the factors (defaults 0), its textures as linear data with their
// own transforms, and what Prism cannot do said: a coat on glass, a coat's normal map.
TEST(GltfLoader, ClearcoatFactorsAndTextures) {
  test::ScratchFolder dir;
  write_png(dir / "coat.png", EncodedImage{1, 1, 3, 8, {200, 100, 50}});
  dir.write("quad.bin", quad_buffer());
  const std::string materials = R"([
    {"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.3,
       "clearcoatTexture": {"index": 0}, "clearcoatRoughnessTexture": {"index": 0,
         "extensions": {"KHR_texture_transform": {"scale": [4, 4]}}}}}},
    {"pbrMetallicRoughness": {"metallicFactor": 0},
     "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}, "KHR_materials_specular": {"specularFactor": 0}}},
    {"extensions": {"KHR_materials_clearcoat": {"clearcoatRoughnessFactor": 0.5}}},
    {"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatNormalTexture": {"index": 0}},
                    "KHR_materials_transmission": {"transmissionFactor": 1}}},
    {"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.5,
                                                "clearcoatNormalTexture": {"index": 0, "scale": 0.5}}}}])";
  const std::string top = R"("extensionsUsed": ["KHR_materials_clearcoat", "KHR_texture_transform"],
    "extensionsRequired": ["KHR_materials_clearcoat"],
    "textures": [{"source": 0}], "images": [{"uri": "coat.png"}],)";
  const Scene s = parse_gltf_text(quad_document("quad.bin", top, materials), dir.path());
  ASSERT_EQ(s.materials.size(), 5u);
  const Material& coated = s.materials[0];
  EXPECT_TRUE(coated.has_clearcoat());
  EXPECT_EQ(coated.type, MaterialType::metallic_roughness);
  EXPECT_FLOAT_EQ(coated.clearcoat, 0.8f);
  EXPECT_FLOAT_EQ(coated.clearcoat_roughness, 0.3f);
  ASSERT_GE(coated.clearcoat_texture, 0);
  ASSERT_GE(coated.clearcoat_roughness_texture, 0);
  EXPECT_EQ(s.textures[coated.clearcoat_texture].encoding, TextureEncoding::linear);
  EXPECT_FLOAT_EQ(s.textures[coated.clearcoat_texture].scale_u, 1.0f);
  EXPECT_FLOAT_EQ(s.textures[coated.clearcoat_roughness_texture].scale_u, 4.0f);  // its own transform
  // A diffuse base (KHR_materials_specular 0) under a smooth coat.
  EXPECT_EQ(s.materials[1].type, MaterialType::diffuse);
  EXPECT_TRUE(s.materials[1].has_clearcoat());
  EXPECT_FLOAT_EQ(s.materials[1].clearcoat_roughness, 0.0f);
  EXPECT_FALSE(s.materials[2].has_clearcoat());  // clearcoatFactor defaults to 0
  EXPECT_EQ(s.materials[3].type, MaterialType::dielectric);
  EXPECT_FALSE(s.materials[3].has_clearcoat());
  EXPECT_TRUE(s.materials[4].has_clearcoat());
  // The coat's own normal map (a normalTextureInfo: its scale multiplies x and y), linear.
  ASSERT_GE(s.materials[4].clearcoat_normal_texture, 0);
  EXPECT_FLOAT_EQ(s.materials[4].clearcoat_normal_scale, 0.5f);
  EXPECT_EQ(s.textures[s.materials[4].clearcoat_normal_texture].encoding, TextureEncoding::linear);
  EXPECT_EQ(s.materials[0].clearcoat_normal_texture, -1);
  int glass_warnings = 0, normal_warnings = 0;
  for (const std::string& w : s.warnings) {
    glass_warnings += w.find("materials[3].extensions.KHR_materials_clearcoat: ignored on a transmitting material") !=
                      std::string::npos;
    normal_warnings += w.find("clearcoatNormalTexture") != std::string::npos;
  }
  EXPECT_EQ(glass_warnings, 1);
  EXPECT_EQ(normal_warnings, 0);
  for (const auto& [coat, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"({"clearcoatFactor": 1.5})", "clearcoatFactor must be in [0, 1]"},
           {R"({"clearcoatFactor": 1, "clearcoatRoughnessFactor": -0.1})", "clearcoatRoughnessFactor must be in [0, 1]"},
           {R"({"clearcoatFactor": 1, "clearcoatTexture": {"index": 9}})", "texture 9 does not exist"},
           {R"({"clearcoatFactor": 1, "clearcoatTexture": 0})", "expected a textureInfo object"}}) {
    const std::string message = gltf_parse_error(quad_document(kDataUri + base64(quad_buffer()), "",
                                                          R"([{"extensions": {"KHR_materials_clearcoat": )" + coat + "}}]"));
    EXPECT_NE(message.find(expected), std::string::npos) << coat << " → " << message;
    EXPECT_NE(message.find("KHR_materials_clearcoat"), std::string::npos) << message;
  }
}

// KHR_mesh_quantization (as gltfpack writes): integer positions, normals and uvs, each
// element padded to 4 bytes, dequantized by the node's transform and the accessors'
// normalized flag. Such a file requires the extension; Prism reads it.
TEST(GltfLoader, QuantizedAttributesAreRead) {
  std::string b;
  // Positions: int16, not normalized, 4 × (x, y, z, pad) = 32 B; dequantized by scale 1/1000.
  append<std::int16_t>(b, {0, 0, 0, 0, 1000, 0, 0, 0, 1000, 1000, 0, 0, 0, 1000, 0, 0});
  // Normals: int8 normalized, 4 × (x, y, z, pad) = 16 B: (0, 0, 127) is +z.
  append<std::int8_t>(b, {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0});
  // UVs: uint16 normalized, 4 × (u, v) = 16 B.
  append<std::uint16_t>(b, {0, 65535, 65535, 65535, 65535, 0, 0, 0});
  append<std::uint16_t>(b, {0, 1, 2, 0, 2, 3});  // 12 B
  const std::string doc = R"({"asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
  "buffers": [{"uri": ")" + kDataUri + base64(b) + R"(", "byteLength": 76}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 32, "byteStride": 8},
                  {"buffer": 0, "byteOffset": 32, "byteLength": 16, "byteStride": 4},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 16},
                  {"buffer": 0, "byteOffset": 64, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5122, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1000,1000,0]},
                {"bufferView": 1, "componentType": 5120, "normalized": true, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5123, "normalized": true, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
  "nodes": [{"mesh": 0, "scale": [0.001, 0.001, 0.001]}],
  "scenes": [{"nodes": [0]}]})";
  const Scene s = parse_gltf_text(doc);
  ASSERT_EQ(s.meshes.size(), 1u);
  const TriangleMesh& m = s.meshes[0];
  EXPECT_EQ(m.positions[2], Vec3f(1000, 1000, 0));
  EXPECT_EQ(m.normals[0], Vec3f(0, 0, 1));
  EXPECT_EQ(m.uvs[1].x, 1.0f);
  EXPECT_EQ(m.uvs[1].y, 1.0f);
  ASSERT_EQ(s.instances.size(), 1u);
  const Vec3f corner = s.instances[0].object_to_world.apply_point(m.positions[2]);
  EXPECT_NEAR(corner.x, 1.0f, 1e-6f);
  EXPECT_NEAR(corner.y, 1.0f, 1e-6f);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("KHR_mesh_quantization"), std::string::npos) << w;
}

// KHR_materials_specular and KHR_materials_ior on an opaque material: the layer's weight
// and colour, the IOR kept for F0, the textures with their encodings (the colour's sRGB,
// the weight's A channel linear) and their own transforms, factor 0 on a plain dielectric
// read as Lambert, no texture kept on glass, bad factors refused.
TEST(GltfLoader, SpecularAndIorOnOpaqueMaterials) {
  test::ScratchFolder dir;
  write_png(dir / "specular.png", EncodedImage{1, 1, 4, 8, {200, 100, 50, 128}});
  dir.write("quad.bin", quad_buffer());
  const std::string materials = R"([
    {"pbrMetallicRoughness": {"metallicFactor": 0},
     "extensions": {"KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [0.8, 0.8, 0.8]},
                    "KHR_materials_ior": {"ior": 1.33}}},
    {"pbrMetallicRoughness": {"metallicFactor": 0},
     "extensions": {"KHR_materials_specular": {"specularColorFactor": [1, 0.5, 0.5], "specularTexture": {"index": 0},
       "specularColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [4, 4]}}}}}},
    {"pbrMetallicRoughness": {"metallicFactor": 0}, "extensions": {"KHR_materials_specular": {"specularFactor": 0}}},
    {"pbrMetallicRoughness": {"metallicFactor": 0.5}, "extensions": {"KHR_materials_specular": {"specularFactor": 0}}},
    {"extensions": {"KHR_materials_specular": {"specularTexture": {"index": 0}},
                    "KHR_materials_transmission": {"transmissionFactor": 1}}}])";
  const std::string top = R"("extensionsUsed": ["KHR_materials_specular", "KHR_texture_transform"],
    "textures": [{"source": 0}], "images": [{"uri": "specular.png"}],)";
  const Scene s = parse_gltf_text(quad_document("quad.bin", top, materials), dir.path());
  ASSERT_EQ(s.materials.size(), 5u);
  EXPECT_EQ(s.materials[0].type, MaterialType::metallic_roughness);
  EXPECT_FLOAT_EQ(s.materials[0].specular, 0.5f);
  EXPECT_EQ(s.materials[0].specular_color, Vec3f(0.8f));
  EXPECT_FLOAT_EQ(s.materials[0].ior, 1.33f);
  EXPECT_EQ(s.materials[0].specular_texture, -1);
  const Material& textured = s.materials[1];
  EXPECT_EQ(textured.specular_color, Vec3f(1, 0.5f, 0.5f));
  ASSERT_GE(textured.specular_texture, 0);
  ASSERT_GE(textured.specular_color_texture, 0);
  EXPECT_EQ(s.textures[textured.specular_texture].encoding, TextureEncoding::linear);
  EXPECT_EQ(s.textures[textured.specular_color_texture].encoding, TextureEncoding::srgb);
  EXPECT_FLOAT_EQ(s.textures[textured.specular_texture].scale_u, 1.0f);
  EXPECT_FLOAT_EQ(s.textures[textured.specular_color_texture].scale_u, 4.0f);  // its own transform
  EXPECT_EQ(s.materials[2].type, MaterialType::diffuse);
  EXPECT_EQ(s.materials[3].type, MaterialType::metallic_roughness);  // a metal keeps its layer
  EXPECT_EQ(s.materials[3].specular, 0.0f);
  EXPECT_EQ(s.materials[4].type, MaterialType::dielectric);
  EXPECT_EQ(s.materials[4].specular_texture, -1);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("KHR_materials_specular"), std::string::npos) << w;
  for (const auto& [specular, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"({"specularFactor": 2})", "specularFactor must be in [0, 1]"},
           {R"({"specularColorFactor": [1, -1, 1]})", "components must be finite and ≥ 0"},
           {R"({"specularColorFactor": [1, 1]})", "must be an array of three numbers"}}) {
    const std::string message = gltf_parse_error(quad_document(kDataUri + base64(quad_buffer()), "",
                                                          R"([{"extensions": {"KHR_materials_specular": )" + specular + "}}]"));
    EXPECT_NE(message.find(expected), std::string::npos) << specular << " → " << message;
  }
}

// KHR_materials_variants: the variant names in the file's order, each primitive wearing
// the material its mappings give the chosen variant (its own material otherwise), and every
// name or index that is not there refused in one line.
TEST(GltfLoader, MaterialVariantsPickTheMappedMaterials) {
  const std::string top = R"("extensionsUsed": ["KHR_materials_variants"],
    "extensions": {"KHR_materials_variants": {"variants": [{"name": "red"}, {"name": "blue"}, {"name": "plain"}]}},)";
  const std::string materials = R"([{"name": "own"}, {"name": "red"}, {"name": "blue"}])";
  const auto document = [&](const std::string& mappings, const std::string& variants_top) {
    std::string d = quad_document(kDataUri + base64(quad_buffer()), variants_top, materials);
    const std::string from = R"("material": 0})";
    return d.replace(d.find(from), from.size(),
                     R"("material": 0, "extensions": {"KHR_materials_variants": {"mappings": )" + mappings + "}}}");
  };
  const std::string mappings = R"([{"material": 1, "variants": [0]}, {"material": 2, "variants": [1]}])";
  const auto material_of = [&](const std::string& variant) {
    const Scene s = parse_gltf_text(document(mappings, top), {}, LoadOptions{.material_variant = variant});
    EXPECT_EQ(s.material_variants, (std::vector<std::string>{"red", "blue", "plain"}));
    for (const TriangleMesh& m : s.meshes) EXPECT_EQ(m.material, s.meshes[0].material);
    for (const std::string& w : s.warnings) EXPECT_EQ(w.find("KHR_materials_variants"), std::string::npos) << w;
    return s.materials[s.meshes[0].material].name;
  };
  EXPECT_EQ(material_of(""), "own");
  EXPECT_EQ(material_of("red"), "red");
  EXPECT_EQ(material_of("blue"), "blue");
  EXPECT_EQ(material_of("plain"), "own");  // a variant no mapping lists: the primitive's own
  const std::string unknown = test::error_of<UsageError>(
      [&] { parse_gltf_text(document(mappings, top), {}, LoadOptions{.material_variant = "green"}); });
  EXPECT_NE(unknown.find("test.gltf: no material variant 'green' (variants: red, blue, plain)"), std::string::npos)
      << unknown;
  for (const auto& [bad_mappings, expected] : std::initializer_list<std::pair<std::string, std::string>>{
           {R"([{"material": 1, "variants": [3]}])", "mappings[0].variants[0]: no such variant"},
           {R"([{"material": 1}])", "mappings[0]: needs an integer 'material' and an array 'variants'"},
           {R"({"material": 1})", "'mappings' must be an array"},
           {R"([{"material": 9, "variants": [0]}])", "material 9 does not exist"}}) {
    const std::string doc = document(bad_mappings, top);
    const std::string message =
        test::error_of<SceneError>([&] { parse_gltf_text(doc, {}, LoadOptions{.material_variant = "red"}); });
    EXPECT_NE(message.find(expected), std::string::npos) << bad_mappings << " → " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  const std::string unnamed = test::error_of<SceneError>([&] {
    parse_gltf_text(document(mappings, R"("extensions": {"KHR_materials_variants": {"variants": [{"label": "x"}]}},)"));
  });
  EXPECT_NE(unnamed.find("extensions.KHR_materials_variants.variants[0]: 'name' must be a string"), std::string::npos)
      << unnamed;
  // A scene without variants takes no --variant, whatever its format.
  const std::string none =
      test::error_of<UsageError>([] { load_scene("cornell-box", LoadOptions{.material_variant = "red"}); });
  EXPECT_NE(none.find("scene 'cornell-box' has no material variants"), std::string::npos) << none;
}

TEST(GltfLoader, BadInputIsAOneLineError) {
  const std::string good_uri = kDataUri + base64(quad_buffer());
  const std::string doc = quad_document(good_uri);
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string d = doc;
    const auto at = d.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return d.replace(at, from.size(), to);
  };
  const std::pair<std::string, std::string> cases[] = {
      {"{", "test.gltf: "},
      {"not json at all", "test.gltf: "},
      {with(R"("asset": {"version": "2.0"}, )", R"("asset": {"version": "2.0"}, "extensionsRequired": ["KHR_draco_mesh_compression"], )"),
       "required extension(s) not supported: KHR_draco_mesh_compression"},
      {with(R"("count": 6)", R"("count": 600)"), "accessor 2"},
      {with(R"("count": 4, "type": "VEC3")", R"("count": 40, "type": "VEC3")"), "accessor 0"},
      {with(R"("byteOffset": 80)", R"("byteOffset": 88)"), "test.gltf: "},
      {with(R"("nodes": [0, 1, 3])", R"("nodes": [0, 1, 3, 99])"), "node 99 does not exist"},
      {with(R"("children": [2])", R"("children": [1])"), "reached twice"},
      {with(R"("children": [2])", R"("children": [2, 2])"), "reached twice"},
      {with(R"("material": 0)", R"("material": 7)"), "material 7 does not exist"},
      {with(R"("yfov": 0.5)", R"("yfov": 4)"), "yfov"},
      {with(R"("type": "VEC2")", R"("type": "VEC3")"), "wrong type"},
      {glb(quad_document(""), quad_buffer()).substr(0, 40), "test.gltf: "},
      {std::string("glTF\x02\0\0\0\xff\xff\xff\x7f", 12), "test.gltf: "},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = gltf_parse_error(text);
    EXPECT_NE(message.find(expected), std::string::npos) << text.substr(0, 80) << " → " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // Every truncation of a GLB fails cleanly.
  const std::string binary = glb(quad_document(""), quad_buffer());
  for (std::size_t n = 0; n < binary.size(); n += 7) EXPECT_THROW(parse_gltf_text(binary.substr(0, n)), SceneError) << n;
}

}  // namespace
}  // namespace prism::loaders
