#include <gtest/gtest.h>

#include "prism/core/error.h"
#include "prism/io/png.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/texture_sampling.h"
#include "prism/scene/loaders/mtl_material.h"
#include "prism/scene/loaders/obj_scene.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

using test::error_of;

constexpr std::string_view kQuadObj = R"(mtllib quad.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 2
o quad
usemtl red
f 1/1/1 2/2/1 3/3/1 4/4/1
)";

constexpr std::string_view kMaterials = R"(newmtl red
Kd 0.8 0.1 0.1
newmtl gold
Kd 0 0 0
Ks 1 0.8 0.3
Ns 50
newmtl plastic
Kd 0.2 0.2 0.8
Ks 0.5 0.5 0.5
Ns 1000
newmtl glass
illum 7
Ni 1.52
newmtl lamp
Kd 0 0 0
Ke 10 10 10
newmtl leaf
Kd 1 1 1
d 0.25
map_Kd leaf.png
)";

TEST(ObjLoader, TriangulatesPolygonsWithNormalsAndUvs) {
  test::ScratchFolder dir;
  dir.write("quad.mtl", kMaterials);
  const auto obj = dir.write("quad.obj", kQuadObj);
  write_png(dir / "leaf.png", EncodedImage{1, 1, 3, 8, {255, 128, 0}});
  const Scene scene = load_scene(obj.string());
  ASSERT_EQ(scene.meshes.size(), 1u);
  const TriangleMesh& mesh = scene.meshes[0];
  EXPECT_EQ(mesh.name, "quad");
  EXPECT_EQ(mesh.triangle_count(), 2u);
  ASSERT_EQ(mesh.positions.size(), 4u);
  ASSERT_EQ(mesh.normals.size(), 4u);
  ASSERT_EQ(mesh.uvs.size(), 4u);
  EXPECT_FLOAT_EQ(mesh.normals[0].z, 1.0f);  // normalised
  EXPECT_FLOAT_EQ(mesh.uvs[0].y, 1.0f);      // OBJ v = 0 (bottom) is Prism's v = 1
  EXPECT_EQ(scene.materials[mesh.material].name, "red");
  EXPECT_EQ(scene.materials.size(), 6u);  // every MTL material, used or not
  EXPECT_GT(scene.camera.eye.z, 0.5f);    // a framing camera in front of the quad
}

TEST(ObjLoader, MapsMtlParametersToMaterials) {
  test::ScratchFolder dir;
  dir.write("quad.mtl", kMaterials);
  write_png(dir / "leaf.png", EncodedImage{1, 1, 3, 8, {255, 128, 0}});
  const Scene scene = load_scene(dir.write("quad.obj", kQuadObj).string());
  const auto& m = scene.materials;
  EXPECT_EQ(m[0].type, MaterialType::diffuse);
  EXPECT_FLOAT_EQ(m[0].base_color.x, 0.8f);
  EXPECT_EQ(m[1].type, MaterialType::conductor);
  EXPECT_FLOAT_EQ(m[1].base_color.y, 0.8f);
  EXPECT_NEAR(m[1].roughness, loaders::roughness_from_phong_exponent(50.0f), 1e-7f);
  EXPECT_EQ(m[2].type, MaterialType::metallic_roughness);
  EXPECT_LT(m[2].roughness, 0.25f);
  EXPECT_EQ(m[3].type, MaterialType::dielectric);
  EXPECT_FLOAT_EQ(m[3].ior, 1.52f);
  EXPECT_TRUE(m[4].is_emissive());
  EXPECT_NEAR(m[4].emission.luminance_nits, 10.0f, 1e-4f);  // Ke as Rec.709 radiance in nits
  EXPECT_EQ(m[5].alpha_mode, AlphaMode::blend);
  EXPECT_FLOAT_EQ(m[5].opacity, 0.25f);
  ASSERT_EQ(m[5].base_color_texture, 0);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_FLOAT_EQ(scene.textures[0].value(0), 1.0f);
  EXPECT_NEAR(scene.textures[0].value(1), 0.2158605f, 1e-6f);  // sRGB 128 decoded
}

// bump / map_Bump is a height map (linear) times its -bm multiplier; norm a tangent-space
// normal map (linear RGB); neither is in the ignored-parameters warning any more.
TEST(ObjLoader, BumpAndNormalMapsFromMtl) {
  test::ScratchFolder dir;
  dir.write("quad.mtl", "newmtl bumpy\nKd 0.5 0.5 0.5\nmap_Bump -bm 0.25 height.png\nnorm normal.png\n"
                        "newmtl plain\nKd 0.5 0.5 0.5\nbump height.png\n");
  write_png(dir / "height.png", EncodedImage{1, 1, 1, 8, {128}});
  write_png(dir / "normal.png", EncodedImage{1, 1, 3, 8, {128, 128, 255}});
  const std::string obj(kQuadObj);
  const Scene scene = load_scene(dir.write("quad.obj", obj).string());
  const Material& bumpy = scene.materials[0];
  ASSERT_GE(bumpy.bump_texture, 0);
  EXPECT_FLOAT_EQ(bumpy.bump_scale, 0.25f);
  EXPECT_FLOAT_EQ(scene.textures[static_cast<std::size_t>(bumpy.bump_texture)].value(0), 128.0f / 255.0f);  // linear
  ASSERT_GE(bumpy.normal_texture, 0);
  EXPECT_FLOAT_EQ(scene.textures[static_cast<std::size_t>(bumpy.normal_texture)].value(2), 1.0f);
  EXPECT_EQ(scene.materials[1].bump_texture, bumpy.bump_texture);  // one file, one texture
  EXPECT_FLOAT_EQ(scene.materials[1].bump_scale, 1.0f);
  for (const std::string& w : scene.warnings) {
    EXPECT_EQ(w.find("bump"), std::string::npos) << w;
    EXPECT_EQ(w.find("norm"), std::string::npos) << w;
  }
  dir.write("quad.mtl", "newmtl bumpy\nnorm height.png\n");
  std::string message = error_of<SceneError>([&] { load_scene(dir.write("grey.obj", obj).string()); });
  EXPECT_NE(message.find("material 'bumpy' norm"), std::string::npos) << message;
  // A missing map names the material and the map that asked for it.
  dir.write("quad.mtl", "newmtl bumpy\nmap_Bump missing.png\n");
  message = error_of<IoError>([&] { load_scene(dir.write("missing.obj", obj).string()); });
  EXPECT_NE(message.find("material 'bumpy' bump: cannot read image"), std::string::npos) << message;
}

// MTL -s and -o scale and offset the texture coordinates (uv_t = s·uv + o with the OBJ's
// upward v, as three.js and Blender read them): a vertex's vt (u, v) must look the image up
// at (s_u u + o_u, 1 − (s_v v + o_v)) in Prism's downward-v image coordinates.
TEST(ObjLoader, MtlScaleAndOffsetMoveTheTextureCoordinates) {
  test::ScratchFolder dir;
  dir.write("quad.mtl", "newmtl moved\nKd 1 1 1\nmap_Kd -s 2 3 1 -o 0.25 0.5 0 tex.png\n"
                        "newmtl plain\nKd 1 1 1\nmap_Kd tex.png\n");
  write_png(dir / "tex.png", EncodedImage{1, 1, 3, 8, {10, 20, 30}});
  const Scene scene = load_scene(dir.write("quad.obj", std::string(kQuadObj)).string());
  const TextureImage& moved = scene.textures[static_cast<std::size_t>(scene.materials[0].base_color_texture)];
  const TextureImage& plain = scene.textures[static_cast<std::size_t>(scene.materials[1].base_color_texture)];
  EXPECT_NE(scene.materials[0].base_color_texture, scene.materials[1].base_color_texture);
  EXPECT_EQ(moved.width, plain.width);  // the same image, its own addressing
  EXPECT_FLOAT_EQ(moved.value(2), plain.value(2));
  const float u = 0.1f, v = 0.2f;  // an OBJ vt; Prism's uv is (u, 1 − v)
  const Vec2f t = apply_uv_transform(moved, Vec2f(u, 1.0f - v));
  EXPECT_NEAR(t.x, 2.0f * u + 0.25f, 1e-6f);
  EXPECT_NEAR(t.y, 1.0f - (3.0f * v + 0.5f), 1e-6f);
  const Vec2f p = apply_uv_transform(plain, Vec2f(u, 1.0f - v));
  EXPECT_NEAR(p.x, u, 1e-6f);
  EXPECT_NEAR(p.y, 1.0f - v, 1e-6f);
  for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("map_Kd"), std::string::npos) << w;
}

// What the MTL reader does not read is named in its one warning: the PBR extension and a
// coloured transmission filter; a white Tf (what exporters write) and Ka are not noise.
TEST(ObjLoader, UnreadPbrExtensionAndTfAreWarned) {
  test::ScratchFolder dir;
  const auto warnings_for = [&](std::string_view mtl) {
    dir.write("quad.mtl", std::string("newmtl m\nKd 0.5 0.5 0.5\n") + std::string(mtl));
    std::string all;
    for (const std::string& w : load_scene(dir.write("quad.obj", std::string(kQuadObj)).string()).warnings)
      all += w + "\n";
    return all;
  };
  EXPECT_NE(warnings_for("Ps 0.3\nmap_Pr r.png\n").find("PBR extension (Ps, map_Pr"), std::string::npos);
  EXPECT_EQ(warnings_for("Pr 0.3\nPm 1\n").find("PBR extension"), std::string::npos);
  EXPECT_NE(warnings_for("Tf 0.2 0.8 0.2\n").find("Tf"), std::string::npos);
  const std::string quiet = warnings_for("Ka 0.1 0.1 0.1\nTf 1 1 1\n");
  EXPECT_EQ(quiet.find("MTL parameters ignored"), std::string::npos) << quiet;
}

// The PBR extension's Pr and Pm (Blender, three.js) make a metallic-roughness material of
// Kd, overriding the Phong reading of Ks/Ns; glass keeps its refraction and says so.
TEST(ObjLoader, PbrExtensionRoughnessAndMetallic) {
  test::ScratchFolder dir;
  dir.write("quad.mtl", "newmtl metal\nKd 0.9 0.6 0.3\nKs 0.5 0.5 0.5\nNs 10\nPr 0.25\nPm 1\n"
                        "newmtl glass\nillum 7\nNi 1.5\nPr 0.5\n");
  dir.write("quad.obj", "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl metal\nf 1 2 3\nusemtl glass\nf 1 3 4\n");
  const Scene s = load_scene((dir / "quad.obj").string());
  const Material* metal = nullptr;
  const Material* glass = nullptr;
  for (const Material& m : s.materials) (m.name == "metal" ? metal : glass) = &m;
  ASSERT_TRUE(metal && glass);
  EXPECT_EQ(metal->type, MaterialType::metallic_roughness);
  EXPECT_EQ(metal->base_color, Vec3f(0.9f, 0.6f, 0.3f));
  EXPECT_FLOAT_EQ(metal->roughness, 0.25f);
  EXPECT_FLOAT_EQ(metal->metallic, 1.0f);
  EXPECT_EQ(glass->type, MaterialType::dielectric);
  bool said = false;
  for (const std::string& w : s.warnings) said |= w.find("Pr/Pm on glass") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(ObjLoader, PhongExponentToRoughness) {
  // α = sqrt(2 / (Ns + 2)): Ns = 0 is α = 1; Ns = 198 is α = 0.1, r = sqrt(0.1).
  EXPECT_FLOAT_EQ(loaders::roughness_from_phong_exponent(0.0f), 1.0f);
  EXPECT_NEAR(loaders::roughness_from_phong_exponent(198.0f), std::sqrt(0.1f), 1e-6f);
}

TEST(ObjLoader, BadInputIsAOneLineError) {
  test::ScratchFolder dir;
  const auto load = [&](std::string_view text) { return load_scene(dir.write("m.obj", text).string()); };
  std::string message = error_of<SceneError>([&] { load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"); });
  EXPECT_NE(message.find("vertex index 7 is out of range"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  message = error_of<SceneError>([&] { load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4\n"); });
  EXPECT_NE(message.find("normal index 4 is out of range"), std::string::npos) << message;
  message = error_of<SceneError>([&] { load("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"); });
  EXPECT_NE(message.find("not finite"), std::string::npos) << message;
  EXPECT_THROW(load("this is not an obj file\n\x01\x02\x03"), SceneError);  // no triangles
  EXPECT_THROW(load(""), SceneError);
  EXPECT_THROW(load_scene((dir / "missing.obj").string()), IoError);
}

TEST(ObjLoader, SkinWeightLinesAreIgnoredBeforeTinyObjLoaderConvertsThem) {
  // Regression (fuzz_obj): tinyobjloader's `vw` extension converted a joint id of 1e40
  // (inf as a float) to int — undefined behaviour, reported by UBSan under the asan preset.
  // Prism has no skinning; the lines become comments, in any line-ending style, and the
  // mesh around them loads as if they were not there.
  test::ScratchFolder dir;
  for (const std::string eol : {"\n", "\r\n", "\r"}) {
    const std::string text = "v 0 0 0" + eol + "  vw 0 1e40 0.5" + eol + "v 1 0 0" + eol + "\tvw 1 2 0.5" + eol +
                             "v 0 1 0" + eol + "f 1 2 3" + eol;
    const Scene scene = load_scene(dir.write("m.obj", text).string());
    EXPECT_EQ(scene.triangle_count(), 1u);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].positions.size(), 3u);
  }
  // A skin-weight line hides nothing: the bad face after it is still reported.
  const std::string message =
      error_of<SceneError>([&] { load_scene(dir.write("n.obj", "vw 0 1 1\nv 0 0 0\nf 1 2 3\n").string()); });
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
  // The fuzzer's input itself.
  EXPECT_NO_FATAL_FAILURE({
    try {
      load_scene((std::filesystem::path(PRISM_SOURCE_DIR) / "tests/scene/loaders/data/fuzz_obj_skin_weight_inf.obj").string());
    } catch (const Error&) {
    }
  });
}

TEST(ObjLoader, DropsZeroAreaTrianglesWithAWarning) {
  test::ScratchFolder dir;
  const Scene scene =
      load_scene(dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 1 1 3\n").string());
  EXPECT_EQ(scene.triangle_count(), 1u);
  bool warned = false;
  for (const auto& w : scene.warnings) warned = warned || w.find("dropped 2 zero-area triangles") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(ObjLoader, MaterialLibrariesAndTexturesMayNotLeaveTheFolder) {
  test::ScratchFolder dir;
  dir.write("secret.mtl", "newmtl x\nKd 1 1 1\n");
  const auto obj = dir.write("inner/m.obj", "mtllib ../secret.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(error_of<SceneError>([&] { load_scene(obj.string()); }).find("leads outside"), std::string::npos);
  EXPECT_NO_THROW(load_scene(obj.string(), LoadOptions{.allow_external_paths = true}));
  dir.write("inner/t.mtl", "newmtl x\nmap_Kd /etc/passwd\n");
  const auto obj2 = dir.write("inner/t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
  EXPECT_NE(error_of<SceneError>([&] { load_scene(obj2.string()); }).find("absolute path"), std::string::npos);
}

TEST(ObjLoader, JsonSceneIncludesObjMeshesByFile) {
  test::ScratchFolder dir;
  dir.write("quad.mtl", kMaterials);
  write_png(dir / "leaf.png", EncodedImage{1, 1, 3, 8, {255, 128, 0}});
  dir.write("quad.obj", kQuadObj);
  dir.write("scene.json", R"({"format": "prism-scene/1",
    "materials": [{"name": "white", "type": "diffuse"}],
    "meshes": [{"name": "a", "file": "quad.obj", "transform": {"translate": [0, 0, -1]}},
               {"name": "b", "file": "quad.obj", "material": "white", "transform": {"scale": [-1, 1, 1]}},
               {"name": "c", "file": "quad.obj"}]})");
  const Scene scene = load_scene((dir / "scene.json").string());
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_FLOAT_EQ(scene.meshes[0].positions[0].z, -1.0f);
  EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "red");
  EXPECT_EQ(scene.materials[scene.meshes[1].material].name, "white");
  // A mirroring transform keeps the front face: winding flipped, normals still +z.
  EXPECT_FLOAT_EQ(scene.meshes[1].normals[0].z, 1.0f);
  EXPECT_EQ(scene.textures.size(), 1u);  // leaf.png once, although two materials use it
}

}  // namespace
}  // namespace prism
