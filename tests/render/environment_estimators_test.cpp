// The integrator under environment maps, equal-area octahedral (pbrt-v4's image infinite
// lights) and equirectangular: a furnace with a constant map, where every estimator must
// give ρ L on a grey floor, and estimator agreement under an uneven map (NEE uses the map's
// sampling density and looks the radiance up at the sampled texel coordinates, BSDF
// sampling does neither, so a density with the wrong Jacobian or a radiance looked up at
// the wrong texel separates them).
#include <gtest/gtest.h>

#include <cmath>

#include "prism/render/renderer.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

using Estimate = test::BlockEstimate;

// A grey (ρ = 0.5) floor facing +y, seen straight down through a narrow camera, under a
// sky of `luminance_nits` × the map, the map's +z turned to world +y.
Scene floor_under_sky(TextureImage map, float luminance_nits, EnvironmentMapping mapping) {
  Scene scene = test::make_grey_floor_seen_from_above(1.0f, 60.0f);
  scene.name = "sky-floor";
  scene.textures.push_back(std::move(map));
  Light sky;
  sky.type = LightType::environment;
  sky.intensity = luminance_nits;
  sky.environment_texture = 0;
  sky.environment_mapping = mapping;
  const float m[3][3] = {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};  // map +z → world +y
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sky.environment_to_world.m[i][j] = m[i][j];
  scene.lights.push_back(sky);
  return scene;
}

Scene floor_under_octahedral_sky(TextureImage map, float luminance_nits) {
  return floor_under_sky(std::move(map), luminance_nits, EnvironmentMapping::equal_area_octahedral);
}

TextureImage grey_map(int width, int height, float (*value)(int x, int y)) {
  TextureImage t;
  t.name = "sky";
  t.width = width;
  t.height = height;
  t.channels = 3;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) t.texels.insert(t.texels.end(), 3, value(x, y));
  return t;
}

TextureImage square_map(int size, float (*value)(int x, int y)) { return grey_map(size, size, value); }

RenderSettings estimator_settings(TransportKind kind, LightEstimator estimator, int spp) {
  return test::direct_light_settings(kind, estimator, spp, 17);
}

// Light sampling and BSDF sampling estimate the same integral, so NEE-only, BSDF-only and
// MIS renders of `scene` must agree within 5σ of their combined noise.
void expect_estimators_agree(const Scene& scene) {
  const Film nee = render(scene, estimator_settings(TransportKind::rgb, LightEstimator::nee_only, 256)).film;
  const Film bsdf = render(scene, estimator_settings(TransportKind::rgb, LightEstimator::bsdf_only, 256)).film;
  const Film mis = render(scene, estimator_settings(TransportKind::rgb, LightEstimator::mis, 256)).film;
  const Estimate a = test::block_estimate(nee, 0, 0, 8, 8), b = test::block_estimate(bsdf, 0, 0, 8, 8),
                 c = test::block_estimate(mis, 0, 0, 8, 8);
  EXPECT_NEAR(a.mean.y, b.mean.y, 5.0 * std::sqrt(a.variance.y + b.variance.y));
  EXPECT_NEAR(c.mean.y, b.mean.y, 5.0 * std::sqrt(c.variance.y + b.variance.y));
  EXPECT_GT(a.mean.y, 0.1);  // the floor is lit at all
}

TEST(EnvironmentOctahedral, FurnaceWithAConstantMap) {
  // ∫ L cos θ dω over the floor's hemisphere = π L; times ρ/π: ρ L = 5 nits for L = 10.
  // 5σ of the film's own noise plus 5e-4 (float accumulation) as the other furnaces.
  const Scene scene = floor_under_octahedral_sky(square_map(8, [](int, int) { return 1.0f; }), 10.0f);
  for (TransportKind kind : {TransportKind::rgb, TransportKind::spectral})
    for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
      const Film film = render(scene, estimator_settings(kind, est, 64)).film;
      const Estimate e = test::block_estimate(film, 0, 0, film.width(), film.height());
      EXPECT_NEAR(e.mean.y, 5.0, 5.0 * std::sqrt(e.variance.y) + 5e-4)
          << "transport " << static_cast<int>(kind) << " estimator " << static_cast<int>(est);
    }
}

TEST(EnvironmentOctahedral, EstimatorsAgreeUnderAnUnevenMap) {
  // Texels from 0 to 4 with a hot spot; light sampling and BSDF sampling estimate the
  // same integral, so their means must agree within 5σ of their combined noise.
  const Scene scene = floor_under_octahedral_sky(
      square_map(16, [](int x, int y) { return (x == 9 && y == 10) ? 50.0f : static_cast<float>((5 * x + 3 * y) % 9) / 2.0f; }),
      2.0f);
  expect_estimators_agree(scene);
}

TEST(EnvironmentEquirectangular, EstimatorsAgreeUnderAnUnevenMap) {
  // The same check for a latitude-longitude map: values 0 to 4 that change from texel to
  // texel in both directions, and a hot spot in the hemisphere the floor faces (columns
  // 16–31 are the map's +z half, φ ∈ (0, π), turned to world +y). Looking light samples' radiance up
  // anywhere but at their own texel (e.g. mirrored in u) moves NEE's mean by many σ.
  const Scene scene = floor_under_sky(
      grey_map(32, 16, [](int x, int y) { return (x == 21 && y == 5) ? 60.0f : static_cast<float>((7 * x + 3 * y) % 9) / 2.0f; }),
      2.0f, EnvironmentMapping::equirectangular);
  expect_estimators_agree(scene);
}

}  // namespace
}  // namespace prism
