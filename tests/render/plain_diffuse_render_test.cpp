// The integrator's plain diffuse path (WavefrontIntegrator::shade_surface<true>) against
// its general path: the Cornell box, whose materials are all plain diffuse, rendered as it
// is and with every material made to take the general path by a texture its lobe does not
// read (a metallic-roughness texture: a Lambertian lobe has no roughness and no metal).
// The two images must be the same bits, in every transport mode and estimator. And the
// plain path's hits shaded several at a time (shade_plain_lanes) against the same hits
// shaded one by one: the same bits again.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "prism/render/material_bsdf.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/loaders/sphere_mesh.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using test::films_identical;

// A grey 1×1 texture: where it were read it would halve roughness and metallic.
TextureImage grey_texel() {
  TextureImage t;
  t.name = "grey";
  t.width = 1;
  t.height = 1;
  t.channels = 3;
  t.texels = {0.5f, 0.5f, 0.5f};
  return t;
}

struct Case {
  TransportKind kind;
  int wavelengths;
  LightEstimator estimator;
};
constexpr Case kCases[] = {{TransportKind::spectral, 4, LightEstimator::mis},
                           {TransportKind::spectral, 8, LightEstimator::nee_only},
                           {TransportKind::spectral, 3, LightEstimator::bsdf_only},
                           {TransportKind::rgb, 3, LightEstimator::mis}};

RenderSettings settings_for(const Case& c) {
  RenderSettings s;
  s.width = 24;
  s.height = 20;
  s.samples_per_pixel = 6;
  s.seed = 5;
  s.threads = 1;
  s.transport.kind = c.kind;
  s.transport.wavelengths = c.wavelengths;
  s.path.estimator = c.estimator;
  return s;
}

std::string label_of(const Case& c) {
  return std::string(c.kind == TransportKind::rgb ? "rgb" : "spectral") + " " + std::to_string(c.wavelengths) +
         ", estimator " + std::to_string(static_cast<int>(c.estimator));
}

TEST(PlainDiffuseRender, SameImageAsTheGeneralPath) {
  const Scene plain = make_cornell_box();
  for (const Material& m : plain.materials) ASSERT_TRUE(is_plain_diffuse(m)) << m.name;
  Scene general = plain;
  general.textures.push_back(grey_texel());
  for (Material& m : general.materials) {
    m.metallic_roughness_texture = 0;
    ASSERT_FALSE(is_plain_diffuse(m)) << m.name;
  }

  for (const Case c : kCases) {
    const RenderSettings s = settings_for(c);
    const std::string label = label_of(c);
    const RenderResult a = render(plain, s);
    const RenderResult b = render(general, s);
    EXPECT_GT(a.film.counts()[0], 0u) << label;
    EXPECT_TRUE(films_identical(a.film, b.film)) << label << ": the plain and the general path differ";
  }
}

// The Cornell box with a smooth sphere (per-vertex normals and uvs, no tangents) of its
// white, and a point and a directional light besides its lamp: delta and infinitely distant
// light samples.
Scene cornell_box_with_smooth_sphere_and_delta_lights() {
  Scene scene = make_cornell_box();
  TriangleMesh sphere = loaders::make_uv_sphere(Vec3f(380.0f, 90.0f, 120.0f), 90.0f, 10);
  sphere.material = 0;
  EXPECT_EQ(scene.materials[0].name, "white");
  EXPECT_FALSE(sphere.normals.empty());
  scene.meshes.push_back(sphere);
  Light point;
  point.type = LightType::point;
  point.position = Vec3f(150.0f, 400.0f, 200.0f);
  point.intensity = 2e5f;
  scene.lights.push_back(point);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = Vec3f(0.3f, -0.8f, 0.52f);
  sun.intensity = 2.0f;
  scene.lights.push_back(sun);
  return scene;
}

// Hits shaded in lanes (WavefrontIntegrator::shade_plain_lanes: eight AVX2 lanes where the
// processor has them, four SSE2 lanes at SimdLevel::sse2) against the same hits shaded
// alone (SimdLevel::scalar): the same bits, in every transport mode and
// estimator, on flat and smooth meshes, with area, point and directional lights.
TEST(PlainDiffuseLanes, SameImageAsShadingAlone) {
  // The lanes sample area-sampled triangle lights themselves and leave the other
  // strategies (and every other emitter) to the light sampler.
  LightSamplerOptions solid_angle;
  solid_angle.triangle = TriangleLightSampling::solid_angle;
  solid_angle.reuse_selection_sample = false;
  for (const Scene& scene : {make_cornell_box(), cornell_box_with_smooth_sphere_and_delta_lights()}) {
    for (const Case c : kCases) {
      for (const LightSamplerOptions& light : {LightSamplerOptions{}, solid_angle}) {
        RenderSettings s = settings_for(c);
        s.path.light = light;
        const RenderResult lanes = render(scene, s);  // eight lanes where the processor has AVX2
        s.path.simd = SimdLevel::sse2;
        const RenderResult four = render(scene, s);
        s.path.simd = SimdLevel::scalar;
        const RenderResult alone = render(scene, s);
        const std::string label = label_of(c) + (scene.lights.empty() ? "" : ", sphere and delta lights") +
                                  (light == solid_angle ? ", solid-angle triangles" : "");
        // Most hits are on the walls, blocks and sphere, all plain diffuse.
        EXPECT_GT(lanes.lane_shaded_hits, lanes.rays / 2) << label;
        EXPECT_GT(four.lane_shaded_hits, four.rays / 2) << label;
        EXPECT_EQ(alone.lane_shaded_hits, 0u) << label;
        EXPECT_TRUE(films_identical(lanes.film, alone.film)) << label << ": lanes and shading alone differ";
        EXPECT_TRUE(films_identical(four.film, alone.film)) << label << ": four lanes and shading alone differ";
      }
    }
  }
}

}  // namespace
}  // namespace prism
