// Generated per-vertex tangents (mesh_tangents.h) and glTF meshes without TANGENT: unit,
// perpendicular to the normal, along +u, with the handedness sign of mirrored uvs.
#include "prism/scene/loaders/mesh_tangents.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "loader_test_files.h"
#include "prism/render/surface_interaction.h"
#include "prism/core/error.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/loaders/mesh_checks.h"
#include "prism/scene/loaders/gltf_scene.h"
#include "prism/scene/loaders/sphere_mesh.h"

namespace prism::loaders {
namespace {

using test::append;

// Float rounding of a few products and one normalisation: 1e-6 is ~10 ε of unit values.
constexpr float kTolerance = 1e-6f;

// The unit quad in the xy plane facing +z, uvs as glTF lays an image on it: u right,
// v down (v = 1 − y).
TriangleMesh quad(std::vector<Vec2f> uvs) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals.assign(4, Vec3f(0, 0, 1));
  m.uvs = std::move(uvs);
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

void expect_tangents(const TriangleMesh& m, const Vec3f& tangent, float sign) {
  ASSERT_EQ(m.tangents.size(), m.positions.size());
  ASSERT_EQ(m.tangent_signs.size(), m.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_NEAR(length(m.tangents[v] - tangent), 0.0f, kTolerance) << "vertex " << v;
    EXPECT_EQ(m.tangent_signs[v], sign) << "vertex " << v;
  }
}

TEST(MeshTangents, FollowPlusUOnAUvMappedQuad) {
  TriangleMesh m = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  ASSERT_TRUE(generate_tangents(m));
  // dP/du = +x; n × t = +y is up the image (towards −v): right-handed, w = +1.
  expect_tangents(m, Vec3f(1, 0, 0), 1.0f);
}

TEST(MeshTangents, MirroredUvsFlipTheTangentAndTheSign) {
  TriangleMesh m = quad({{1, 1}, {0, 1}, {0, 0}, {1, 0}});  // u = 1 − x
  ASSERT_TRUE(generate_tangents(m));
  // dP/du = −x, and n × t = −y now points down the image: w = −1.
  expect_tangents(m, Vec3f(-1, 0, 0), -1.0f);
}

TEST(MeshTangents, RotatedAndScaledUvs) {
  // u = 2y, v = 3x: a quarter turn of the usual layout (with scales), not a mirror.
  TriangleMesh m = quad({{0, 0}, {0, 3}, {2, 3}, {2, 0}});
  ASSERT_TRUE(generate_tangents(m));
  expect_tangents(m, Vec3f(0, 1, 0), 1.0f);
}

TEST(MeshTangents, UnitPerpendicularAndAlongUOnASphere) {
  // make_uv_sphere: u around from +x towards −z, v from +y down, so dP/du points along
  // (−sin φ, 0, −cos φ) with φ = atan2(−z, x), and n × t points north (up the image).
  TriangleMesh m = make_uv_sphere(Vec3f(0.0f), 2.0f, 24);
  ASSERT_TRUE(generate_tangents(m));
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    const Vec3f& t = m.tangents[v];
    const Vec3f n = normalize(m.normals[v]);
    ASSERT_NEAR(length(t), 1.0f, kTolerance);
    ASSERT_NEAR(dot(t, n), 0.0f, kTolerance);
    EXPECT_EQ(m.tangent_signs[v], 1.0f) << v;
    const Vec3f p = m.positions[v] / 2.0f;
    const float sin_theta = std::sqrt(p.x * p.x + p.z * p.z);
    if (sin_theta < 0.2f) continue;  // pole rows: φ of the vertex says little about its wedge
    const float phi = std::atan2(-p.z, p.x);
    const Vec3f along_u(-std::sin(phi), 0.0f, -std::cos(phi));
    // Angle-weighted mean of the adjacent triangles' dP/du: off the analytic direction
    // by about half a segment (7.5°) at most, at the uv seam's copies; cos 10° ≈ 0.985.
    EXPECT_GT(dot(t, along_u), 0.985f) << v;
  }
}

TEST(MeshTangents, MirrorSeamVerticesTakeOneSide) {
  // Two quads sharing the edge x = 1, the right one's uvs mirrored (u = 1 − |x − 1|), as
  // symmetric models lay out half a texture. Off the seam each side gets its own frame; a
  // seam vertex takes one side's whole frame (tangent and sign together), never a blend.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  m.normals.assign(6, Vec3f(0, 0, 1));
  m.uvs = {{0, 1}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {0, 0}};
  m.indices = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
  ASSERT_TRUE(generate_tangents(m));
  for (std::size_t v : {0u, 3u}) {
    EXPECT_NEAR(length(m.tangents[v] - Vec3f(1, 0, 0)), 0.0f, kTolerance);
    EXPECT_EQ(m.tangent_signs[v], 1.0f);
  }
  for (std::size_t v : {2u, 5u}) {
    EXPECT_NEAR(length(m.tangents[v] - Vec3f(-1, 0, 0)), 0.0f, kTolerance);
    EXPECT_EQ(m.tangent_signs[v], -1.0f);
  }
  for (std::size_t v : {1u, 4u}) {
    const float side = m.tangent_signs[v];
    EXPECT_NEAR(length(m.tangents[v] - Vec3f(side, 0, 0)), 0.0f, kTolerance) << v;
  }
}

TEST(MeshTangents, NeedsNormalsAndUvs) {
  TriangleMesh m = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  m.normals.clear();
  EXPECT_FALSE(generate_tangents(m));
  EXPECT_TRUE(m.tangents.empty());
}

TEST(MeshTangents, MeshChecksRefuseBadSigns) {
  TriangleMesh m = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  ASSERT_TRUE(generate_tangents(m));
  TriangleMesh short_signs = m;
  short_signs.tangent_signs.pop_back();
  EXPECT_THROW(check_and_clean_mesh(short_signs, "quad"), SceneError);
  TriangleMesh half = m;
  half.tangent_signs[2] = 0.5f;
  EXPECT_THROW(check_and_clean_mesh(half, "quad"), SceneError);
  EXPECT_EQ(check_and_clean_mesh(m, "quad"), 0u);
}

// A GLB of the +z quad with normals and uvs (u right, v down), and optionally TANGENT
// with w = −1.
std::string quad_glb(bool with_tangents) {
  std::string bin;
  append<float>(bin, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});  // 48 B positions
  append<float>(bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});  // 48 B normals
  append<float>(bin, {0, 1, 1, 1, 1, 0, 0, 0});              // 32 B uvs
  append<std::uint16_t>(bin, {0, 1, 2, 0, 2, 3, 0, 0});      // 16 B indices (padded)
  append<float>(bin, {0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1});  // 64 B tangents
  const std::string tangent = with_tangents ? R"(, "TANGENT": 4)" : "";
  const std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 208}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 144, "byteLength": 64}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
                {"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC4"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2)" +
                     tangent + R"(}, "indices": 3}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
  return test::glb(json, bin);
}

Scene parse_glb(const std::string& bytes) {
  return parse_gltf_scene({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()}, "quad.glb", {});
}

TEST(MeshTangents, GltfWithoutTangentGetsGeneratedOnes) {
  const Scene s = parse_glb(quad_glb(false));
  ASSERT_EQ(s.meshes.size(), 1u);
  expect_tangents(s.meshes[0], Vec3f(1, 0, 0), 1.0f);
}

TEST(MeshTangents, GltfTangentsAndTheirSignsAreKept) {
  const Scene s = parse_glb(quad_glb(true));
  ASSERT_EQ(s.meshes.size(), 1u);
  expect_tangents(s.meshes[0], Vec3f(0, 1, 0), -1.0f);  // the file's, not generated
}

TEST(MeshTangents, MirroredInstancesFlipTheSign) {
  // The bitangent sign · n × t must stay the mirrored image of the original bitangent:
  // under x → −x, t = +x becomes −x, n = +z stays, so n × t turns from +y to −y while the
  // mirrored bitangent is still +y: the sign flips.
  Scene scene;
  scene.materials.emplace_back();
  scene.meshes.push_back(quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}}));
  ASSERT_TRUE(generate_tangents(scene.meshes[0]));
  scene.instances.push_back({0, Transform::scale(Vec3f(-1, 1, 1))});
  const Scene flat = flatten_instances(scene);
  const TriangleMesh& m = flat.meshes[0];
  for (std::size_t v = 0; v < 4; ++v) {
    const Vec3f bitangent = cross(m.normals[v], m.tangents[v]) * m.tangent_signs[v];
    EXPECT_NEAR(length(bitangent - Vec3f(0, 1, 0)), 0.0f, kTolerance);
  }
}

TEST(MeshTangents, ShadingFrameFollowsTheTangent) {
  // With u along +y on the quad, the hit's frame has s = +y (without tangents it would be
  // whatever Frame::from_normal(+z) gives: +x).
  Scene scene;
  scene.materials.emplace_back();
  scene.meshes.push_back(quad({{0, 0}, {0, 3}, {2, 3}, {2, 0}}));
  ASSERT_TRUE(generate_tangents(scene.meshes[0]));
  Hit hit;
  hit.u = 0.2f;
  hit.v = 0.3f;
  const SurfaceInteraction si = surface_interaction(scene, hit, Ray{Vec3f(0.5f, 0.5f, 1.0f), Vec3f(0, 0, -1)});
  EXPECT_NEAR(length(si.shading.s - Vec3f(0, 1, 0)), 0.0f, kTolerance);
  EXPECT_NEAR(length(si.shading.n - Vec3f(0, 0, 1)), 0.0f, kTolerance);
  EXPECT_NEAR(length(cross(si.shading.s, si.shading.t) - si.shading.n), 0.0f, kTolerance);  // right-handed
  scene.meshes[0].tangents.clear();
  const SurfaceInteraction plain = surface_interaction(scene, hit, Ray{Vec3f(0.5f, 0.5f, 1.0f), Vec3f(0, 0, -1)});
  EXPECT_GT(length(plain.shading.s - Vec3f(0, 1, 0)), 0.5f);
}

}  // namespace
}  // namespace prism::loaders
