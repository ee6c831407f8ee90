// Tangent-space normal maps (render/normal_mapping.h): the frame arithmetic against its
// definition, the triangle tangent's handedness against the glTF loader's generated
// tangents, and at render level the one thing a normal map must do: a Lambertian floor
// under a delta directional light shows ρ/π · E · cos(light, mapped normal), whose ratio
// to the unmapped floor is that cosine exactly (no random numbers reach a delta light's
// estimate), so the map's axes, signs and scale are each checked by a direction.
#include "prism/render/normal_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/render/renderer.h"
#include "prism/scene/loaders/mesh_tangents.h"
#include "support/film_statistics.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;

Vec3f encode(const Vec3f& n) { return n * 0.5f + Vec3f(0.5f); }  // a normal map's texel

// A normal map of one texel holding the unit normal `n` (tangent space).
TextureImage one_texel_normal_map(const Vec3f& n) {
  TextureImage t;
  t.name = "normal-map";
  t.width = t.height = 1;
  t.channels = 3;
  const Vec3f rgb = encode(n / length(n));
  t.texels = {rgb.x, rgb.y, rgb.z};
  return t;
}

void expect_orthonormal(const Frame& f) {
  EXPECT_NEAR(length(f.s), 1.0f, 1e-6f);
  EXPECT_NEAR(length(f.t), 1.0f, 1e-6f);
  EXPECT_NEAR(length(f.n), 1.0f, 1e-6f);
  EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-6f);
  EXPECT_NEAR(dot(f.t, f.n), 0.0f, 1e-6f);
  EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-6f);
  const Vec3f handed = cross(f.s, f.t);  // right-handed, as every Frame
  EXPECT_NEAR(dot(handed, f.n), 1.0f, 1e-6f);
}

void expect_near(const Vec3f& a, const Vec3f& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// Tangent +x, bitangent −z, normal +y: the floor below (u along +x, v along +z, so "up the
// image" is −z).
const Frame kFloorFrame{Vec3f(1, 0, 0), Vec3f(0, 0, -1), Vec3f(0, 1, 0)};

TEST(NormalMapping, TheFlatTexelKeepsTheFrame) {
  const Frame f = normal_mapped_frame(kFloorFrame, 1.0f, encode(Vec3f(0, 0, 1)), 1.0f, kFloorFrame.n);
  expect_near(f.n, kFloorFrame.n, 1e-7f);
  expect_near(f.s, kFloorFrame.s, 1e-7f);
  expect_near(f.t, kFloorFrame.t, 1e-7f);
}

TEST(NormalMapping, TexelAxesAreTangentBitangentAndNormal) {
  const float c = std::cos(30.0f * kDegree), s = std::sin(30.0f * kDegree);
  // +x of the map tilts towards the tangent, +y towards the bitangent (sign · n × t).
  const Frame x = normal_mapped_frame(kFloorFrame, 1.0f, encode(Vec3f(s, 0, c)), 1.0f, kFloorFrame.n);
  expect_near(x.n, Vec3f(s, c, 0), 1e-6f);
  expect_orthonormal(x);
  EXPECT_NEAR(x.t.z, -1.0f, 1e-6f);  // the tangent turns about the bitangent, which stays
  const Frame y = normal_mapped_frame(kFloorFrame, 1.0f, encode(Vec3f(0, s, c)), 1.0f, kFloorFrame.n);
  expect_near(y.n, Vec3f(0, c, -s), 1e-6f);
  expect_orthonormal(y);
  expect_near(y.s, kFloorFrame.s, 1e-6f);  // ... and the tangent stays when the normal turns about it
  // Mirrored uvs (TANGENT.w = −1) flip the map's y, not its x.
  const Frame mirrored = normal_mapped_frame(kFloorFrame, -1.0f, encode(Vec3f(s, s, c)), 1.0f, kFloorFrame.n);
  const Vec3f expected = Vec3f(s, c, s) / length(Vec3f(s, c, s));
  expect_near(mirrored.n, expected, 1e-6f);
}

TEST(NormalMapping, ScaleMultipliesTheMapsXAndY) {
  const Vec3f texel = encode(Vec3f(0.6f, 0.0f, 0.8f));
  const Frame flat = normal_mapped_frame(kFloorFrame, 1.0f, texel, 0.0f, kFloorFrame.n);
  expect_near(flat.n, kFloorFrame.n, 1e-6f);
  // glTF 2.0 §5.20 (normalTextureInfo.scale): (x·scale, y·scale, z), then normalised.
  const Frame half = normal_mapped_frame(kFloorFrame, 1.0f, texel, 0.5f, kFloorFrame.n);
  const Vec3f expected = Vec3f(0.3f, 0.8f, 0.0f) / length(Vec3f(0.3f, 0.8f, 0.0f));
  expect_near(half.n, expected, 1e-6f);
}

TEST(NormalMapping, NormalsBelowTheSurfaceAreLiftedAndEmptyTexelsIgnored) {
  // A map normal pointing into the surface: lifted to just above it, still a valid frame.
  const Frame below = normal_mapped_frame(kFloorFrame, 1.0f, encode(Vec3f(0.8f, 0.0f, -0.6f)), 1.0f, kFloorFrame.n);
  EXPECT_GE(dot(below.n, kFloorFrame.n), 0.01f - 1e-6f);
  EXPECT_LT(dot(below.n, kFloorFrame.n), 0.02f);
  EXPECT_GT(below.n.x, 0.99f);  // the lift keeps its direction along the surface
  expect_orthonormal(below);
  // (½, ½, ½) decodes to the zero vector, NaN to nothing: the frame stays as it was.
  const Frame zero = normal_mapped_frame(kFloorFrame, 1.0f, Vec3f(0.5f), 1.0f, kFloorFrame.n);
  expect_near(zero.n, kFloorFrame.n, 0.0f);
  const Frame nan = normal_mapped_frame(kFloorFrame, 1.0f, Vec3f(std::nanf("")), 1.0f, kFloorFrame.n);
  expect_near(nan.n, kFloorFrame.n, 0.0f);
}

// A 2-triangle floor as in the render test below, and its mirror image in u.
TriangleMesh floor_mesh(bool mirrored_u) {
  TriangleMesh floor;
  floor.positions = {{-100, 0, -100}, {100, 0, -100}, {100, 0, 100}, {-100, 0, 100}};
  floor.indices = {0, 2, 1, 0, 3, 2};  // front face up (+y)
  floor.normals.assign(4, Vec3f(0, 1, 0));
  floor.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (mirrored_u)
    for (Vec2f& uv : floor.uvs) uv.x = 1.0f - uv.x;
  return floor;
}

// The triangle tangent (meshes without per-vertex tangents) and the glTF loader's
// generated tangents must agree on direction and handedness, or a normal map would turn
// one way in a glTF scene and the other in a JSON or pbrt-v4 one.
TEST(NormalMapping, TriangleTangentAgreesWithGeneratedTangents) {
  for (const bool mirrored : {false, true}) {
    TriangleMesh mesh = floor_mesh(mirrored);
    ASSERT_TRUE(loaders::generate_tangents(mesh));
    for (std::uint32_t triangle = 0; triangle < 2; ++triangle) {
      Vec3f tangent;
      float sign = 0.0f;
      ASSERT_TRUE(triangle_tangent(mesh, triangle, tangent, sign));
      const Vec3f expected_tangent(mirrored ? -1.0f : 1.0f, 0.0f, 0.0f);
      expect_near(tangent / length(tangent), expected_tangent, 1e-6f);
      EXPECT_EQ(sign, mirrored ? -1.0f : 1.0f);
      const std::uint32_t corner = mesh.indices[3 * triangle];
      expect_near(mesh.tangents[corner], expected_tangent, 1e-6f);
      EXPECT_EQ(mesh.tangent_signs[corner], sign);
      // Unmirrored, sign · n × t points up the image: towards −v, which is −z here.
      const Vec3f up_the_image = cross(Vec3f(0, 1, 0), tangent / length(tangent)) * sign;
      expect_near(up_the_image, Vec3f(0, 0, -1), 1e-6f);
    }
  }
  TriangleMesh degenerate = floor_mesh(false);
  degenerate.uvs.assign(4, Vec2f(0.5f, 0.5f));
  Vec3f tangent;
  float sign = 0.0f;
  EXPECT_FALSE(triangle_tangent(degenerate, 0, tangent, sign));
}

// The sunlit floor (test_scenes.h), optionally with a 1×1 normal map holding `map_normal`
// (tangent-space), through the floor's triangles' tangents or per-vertex ones (the glTF
// path). The mean of the image's red channel.
double floor_red(const Vec3f& toward_light, const Vec3f* map_normal, bool mirrored_u = false,
                 bool per_vertex_tangents = false) {
  Scene scene = test::make_sunlit_uv_floor(toward_light, mirrored_u);
  if (map_normal) {
    scene.textures.push_back(one_texel_normal_map(*map_normal));
    scene.materials[0].normal_texture = 0;
  }
  if (per_vertex_tangents) loaders::generate_tangents(scene.meshes[0]);
  return test::direct_light_mean_red(scene);
}

Vec3f tilted(float degrees, const Vec3f& towards) {  // the floor's normal +y tilted towards a direction in the floor
  return Vec3f(0, std::cos(degrees * kDegree), 0) + towards * std::sin(degrees * kDegree);
}

// Each pixel is ρ/π · E · cos θ, computed in float: a relative error of a few 1e-7 per
// operation over some twenty operations; 1e-5 leaves room and is far below any wrong axis
// (which changes the cosine by ≥ 0.1).
constexpr double kNormalMapRelative = 1e-5;

TEST(NormalMapping, LambertianFloorShowsTheCosineToTheMappedNormal) {
  const double unmapped = floor_red(Vec3f(0, 1, 0), nullptr);
  ASSERT_GT(unmapped, 0.0);
  // A map tilting the normal 60°: a light overhead falls at 60° to it.
  const Vec3f tilt60(std::sin(60.0f * kDegree), 0.0f, std::cos(60.0f * kDegree));
  EXPECT_NEAR(floor_red(Vec3f(0, 1, 0), &tilt60) / unmapped, 0.5, 0.5 * kNormalMapRelative);
  // The map's +x is the tangent (+u, +x here): a light 40° towards +x is head-on to a
  // normal tilted 40° by the map's x; one 40° towards −x falls at 80°.
  const Vec3f x40(std::sin(40.0f * kDegree), 0.0f, std::cos(40.0f * kDegree));
  EXPECT_NEAR(floor_red(tilted(40, Vec3f(1, 0, 0)), &x40) / unmapped, 1.0, kNormalMapRelative);
  EXPECT_NEAR(floor_red(tilted(40, Vec3f(-1, 0, 0)), &x40) / unmapped, std::cos(80.0 * std::numbers::pi / 180.0),
              kNormalMapRelative);
  // The map's +y runs up the image (towards −v, −z here).
  const Vec3f y40(0.0f, std::sin(40.0f * kDegree), std::cos(40.0f * kDegree));
  EXPECT_NEAR(floor_red(tilted(40, Vec3f(0, 0, -1)), &y40) / unmapped, 1.0, kNormalMapRelative);
  EXPECT_NEAR(floor_red(tilted(40, Vec3f(0, 0, 1)), &y40) / unmapped, std::cos(80.0 * std::numbers::pi / 180.0),
              kNormalMapRelative);
  // The same through per-vertex tangents (the glTF path) instead of the triangle's.
  EXPECT_NEAR(floor_red(tilted(40, Vec3f(0, 0, -1)), &y40, false, true) / unmapped, 1.0, kNormalMapRelative);
  EXPECT_NEAR(floor_red(tilted(40, Vec3f(1, 0, 0)), &x40, false, true) / unmapped, 1.0, kNormalMapRelative);
}

TEST(NormalMapping, MirroredUvsMirrorTheMapsXOnly) {
  const double unmapped = floor_red(Vec3f(0, 1, 0), nullptr);
  // u runs along −x now: the map's +x tilts towards −x; its +y still runs up the image.
  const Vec3f x40(std::sin(40.0f * kDegree), 0.0f, std::cos(40.0f * kDegree));
  const Vec3f y40(0.0f, std::sin(40.0f * kDegree), std::cos(40.0f * kDegree));
  for (const bool per_vertex : {false, true}) {
    EXPECT_NEAR(floor_red(tilted(40, Vec3f(-1, 0, 0)), &x40, true, per_vertex) / unmapped, 1.0, kNormalMapRelative);
    EXPECT_NEAR(floor_red(tilted(40, Vec3f(0, 0, -1)), &y40, true, per_vertex) / unmapped, 1.0, kNormalMapRelative);
  }
}

TEST(NormalMapping, TheNormalAovShowsTheMappedNormal) {
  Scene scene = test::make_sunlit_uv_floor(Vec3f(0, 1, 0));
  scene.textures.push_back(one_texel_normal_map(Vec3f(0.6f, 0.0f, 0.8f)));
  scene.materials[0].normal_texture = 0;
  RenderSettings settings;
  settings.width = settings.height = 4;
  settings.samples_per_pixel = 1;
  settings.aovs.normal = true;
  settings.threads = 1;
  const RenderResult r = render(scene, settings, RenderHooks{});
  const Vec3d n = r.film.normal_mean(5);
  EXPECT_NEAR(n.x, 0.6, 1e-5);
  EXPECT_NEAR(n.y, 0.8, 1e-5);
  EXPECT_NEAR(n.z, 0.0, 1e-5);
}

// The white furnace at render level: a white (ρ = 1) floor whose map tilts its normal by
// 50°, under a uniform sky of luminance 1. Whatever the floor's relief, an albedo-1 surface
// under a uniform sky sends back the sky's radiance: 1. Microfacet normal mapping does
// (the walk on the microsurface loses nothing); classic normal mapping keeps only the
// directions above both the shading and the geometric surface, ∫ cos θs / π over them =
// (1 + cos 50°)/2 = 0.821. Both within 5σ of the render's own noise (MIS of the sky's
// light samples and the BSDF's; with microfacet mapping also light or BSDF sampling alone,
// which the walks longer than one facet event must complement in the same way).
test::BlockEstimate furnace_floor(NormalMapping model, LightEstimator estimator = LightEstimator::mis) {
  Scene scene = test::make_sunlit_uv_floor(Vec3f(0, 1, 0));
  scene.lights.clear();
  Light sky;
  sky.type = LightType::environment;
  sky.intensity = 1.0f;
  scene.lights.push_back(sky);
  scene.materials[0].base_color = Vec3f(1.0f);
  scene.textures.push_back(one_texel_normal_map(Vec3f(std::sin(50.0f * kDegree), 0.0f, std::cos(50.0f * kDegree))));
  scene.materials[0].normal_texture = 0;
  RenderSettings settings;
  settings.width = settings.height = 8;
  settings.samples_per_pixel = 256;
  settings.path.max_depth = 1;  // the floor sees only the sky
  settings.path.normal_mapping = model;
  settings.path.estimator = estimator;
  settings.transport.kind = TransportKind::rgb;
  return test::block_estimate(render(scene, settings, RenderHooks{}).film, 0, 0, 8, 8);
}

TEST(NormalMapping, MicrofacetNormalMappingPassesTheWhiteFurnace) {
  for (const LightEstimator estimator : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
    const test::BlockEstimate microfacet = furnace_floor(NormalMapping::microfacet, estimator);
    // BSDF sampling alone gives every sample exactly the sky's 1 (each walk's weight is 1):
    // no noise, only float rounding (≈ 10⁻⁸), hence the 10⁻⁶ floor.
    EXPECT_NEAR(microfacet.mean.y, 1.0, 5.0 * std::sqrt(microfacet.variance.y) + 1e-6) << static_cast<int>(estimator);
  }
  const test::BlockEstimate classic = furnace_floor(NormalMapping::classic);
  EXPECT_NEAR(classic.mean.y, (1.0 + std::cos(50.0 * std::numbers::pi / 180.0)) / 2.0,
              5.0 * std::sqrt(classic.variance.y));
}

}  // namespace
}  // namespace prism
