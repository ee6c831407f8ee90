// Alpha coverage in the accelerator's intersection filters (scene/surface_alpha.h):
// MASK cut-outs from a texture's alpha, BLEND as stochastic coverage, for closest-hit and
// shadow (occlusion) queries alike, deterministic per ray.
#include "prism/accel/embree_accel.h"

#include <cmath>

#include <gtest/gtest.h>

#include "prism/core/pcg32.h"
#include "prism/scene/surface_alpha.h"

namespace prism {
namespace {

// A unit quad in the plane z = `z` spanning x, y ∈ [0, 1], uv = (x, y).
TriangleMesh quad(float z, std::uint32_t material) {
  TriangleMesh m;
  m.name = "quad";
  m.positions = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.material = material;
  return m;
}

// Front quad (material 0, alpha-tested) at z = 0, opaque back quad (material 1) at z = 1.
Scene two_quads(Material front) {
  Scene s;
  s.materials = {front, Material{}};
  s.meshes = {quad(0.0f, 0), quad(1.0f, 1)};
  // A 4×1 RGBA texture whose alpha is 1, 1, 0, 0 from left to right: at texel centres
  // (u = 1/8, 3/8, 5/8, 7/8) bilinear filtering returns exactly those values.
  TextureImage t;
  t.name = "alpha";
  t.width = 4;
  t.height = 1;
  t.channels = 4;
  t.texels = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 0};
  t.wrap_u = t.wrap_v = TextureWrap::clamp;
  s.textures.push_back(t);
  return s;
}

Ray toward_quads(float x, float y) { return Ray{{x, y, -1.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, 10.0f}; }

TEST(AlphaCoverage, MaskCutsOutWhereTextureAlphaIsBelowTheCutoff) {
  Material front;
  front.alpha_mode = AlphaMode::mask;
  front.alpha_cutoff = 0.5f;
  front.base_color_texture = 0;
  const Scene scene = two_quads(front);
  const EmbreeAccel accel(scene);
  Hit hit;
  ASSERT_TRUE(accel.intersect(toward_quads(1.0f / 8.0f, 0.5f), hit));
  EXPECT_EQ(hit.mesh, 0u);
  EXPECT_FLOAT_EQ(hit.t, 1.0f);
  ASSERT_TRUE(accel.intersect(toward_quads(7.0f / 8.0f, 0.5f), hit));
  EXPECT_EQ(hit.mesh, 1u) << "the ray should pass the cut-out and hit the back quad";
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
  // Shadow rays see the same cut-outs: a segment ending before the back quad.
  const auto segment = [](float x) { return Ray{{x, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, 1.5f}; };
  EXPECT_TRUE(accel.occluded(segment(1.0f / 8.0f)));
  EXPECT_FALSE(accel.occluded(segment(7.0f / 8.0f)));
}

TEST(AlphaCoverage, OpaqueMaterialsIgnoreTextureAlpha) {
  Material front;  // alpha_mode opaque, same texture
  front.base_color_texture = 0;
  const Scene scene = two_quads(front);
  const EmbreeAccel accel(scene);
  Hit hit;
  ASSERT_TRUE(accel.intersect(toward_quads(7.0f / 8.0f, 0.5f), hit));
  EXPECT_EQ(hit.mesh, 0u);
}

TEST(AlphaCoverage, BlendPassesRaysWithProbabilityOneMinusOpacity) {
  Material front;
  front.alpha_mode = AlphaMode::blend;
  front.opacity = 0.3f;
  const Scene scene = two_quads(front);
  const EmbreeAccel accel(scene);
  Pcg32 rng(7, 3);
  constexpr int kRays = 20000;
  int front_hits = 0, shadowed = 0;
  for (int i = 0; i < kRays; ++i) {
    // Origins inside [0.1, 0.9]², tilts below 0.05 per unit: every ray crosses both quads.
    const Ray ray{{0.1f + 0.8f * rng.next_float(), 0.1f + 0.8f * rng.next_float(), -1.0f},
                  normalize(Vec3f(0.1f * (rng.next_float() - 0.5f), 0.1f * (rng.next_float() - 0.5f), 1.0f)),
                  0.0f, 10.0f};
    Hit hit;
    if (accel.intersect(ray, hit) && hit.mesh == 0) ++front_hits;
    Hit again;
    accel.intersect(ray, again);
    EXPECT_EQ(again.mesh, hit.mesh) << "the same ray must decide the same way";
    Ray shadow = ray;
    shadow.t_max = 1.2f;  // ends before the back quad for these directions
    if (accel.occluded(shadow)) ++shadowed;
  }
  // Binomial: σ = sqrt(0.3·0.7/20000) = 0.0032; 5σ bounds a false failure below 1e-6.
  const double p_hit = static_cast<double>(front_hits) / kRays;
  const double p_shadow = static_cast<double>(shadowed) / kRays;
  EXPECT_NEAR(p_hit, 0.3, 0.016);
  EXPECT_NEAR(p_shadow, 0.3, 0.016);
}

TEST(AlphaCoverage, SurfaceAlphaIsOpacityTimesTextureAlpha) {
  Material front;
  front.alpha_mode = AlphaMode::blend;
  front.opacity = 0.5f;
  front.base_color_texture = 0;
  const Scene scene = two_quads(front);
  // Triangle 0 is (0,0), (1,0), (1,1): barycentrics (b1, b2) = (x − y, y) at (x, y).
  EXPECT_FLOAT_EQ(surface_alpha(scene, scene.meshes[0], 0, 1.0f / 8.0f - 0.05f, 0.05f), 0.5f);
  EXPECT_FLOAT_EQ(surface_alpha(scene, scene.meshes[0], 0, 7.0f / 8.0f - 0.05f, 0.05f), 0.0f);
  EXPECT_TRUE(has_alpha_coverage(front));
  Material plain;
  plain.alpha_mode = AlphaMode::blend;  // opacity 1 and no texture: nothing to test
  EXPECT_FALSE(has_alpha_coverage(plain));
}

}  // namespace
}  // namespace prism
