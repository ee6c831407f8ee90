// A thin-walled glass pane does not shift what is seen through it (render level): the
// camera looks down through a pane tilted 45° at an emissive floor whose emission
// texture runs from red to green across the view. Through the pane every pixel keeps the
// colour it has without the pane and is dimmed by the slab's transmittance T'; a plain
// (thick, single-interface) dielectric in the same place bends the rays and shifts the
// pattern, which the same measurement detects.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/bsdf/fresnel.h"
#include "prism/bsdf/thin_dielectric.h"
#include "prism/render/renderer.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

constexpr int kPaneImageSizePx = 16;

Scene floor_behind_pane(int pane_kind) {  // 0: none, 1: thin-walled, 2: plain dielectric
  Scene scene;
  scene.name = "pane";
  Material floor;
  floor.base_color = Vec3f(0.0f);
  floor.emission.color = Vec3f(1.0f);
  floor.emission.luminance_nits = 10.0f;
  floor.emission.texture = 0;
  Material glass;
  glass.type = MaterialType::dielectric;
  glass.base_color = Vec3f(1.0f);  // clear: the base colour tints transmission
  glass.roughness = 0.0f;
  glass.ior = 1.5f;
  glass.thin_walled = pane_kind == 1;
  scene.materials = {floor, glass};
  TriangleMesh f;
  f.positions = {{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}};
  f.indices = {0, 2, 1, 0, 3, 2};
  f.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene.meshes.push_back(f);
  if (pane_kind != 0) {
    // Square of half-size 10 through (0, 45, 0), normal (0, 1, 1)/√2.
    TriangleMesh pane;
    const float h = 10.0f, d = 10.0f / std::numbers::sqrt2_v<float>;
    pane.positions = {{-h, 45 + d, -d}, {h, 45 + d, -d}, {h, 45 - d, d}, {-h, 45 - d, d}};
    pane.indices = {0, 2, 1, 0, 3, 2};
    pane.material = 1;
    scene.meshes.push_back(pane);
  }
  // 16 texels along v (world z, the direction the pane's tilt would bend rays): red
  // fades to green linearly, so a shift changes every pixel.
  TextureImage t;
  t.name = "ramp";
  t.width = 1;
  t.height = 16;
  t.channels = 3;
  for (int i = 0; i < 16; ++i) {
    const float g = static_cast<float>(i) / 15.0f;
    t.texels.insert(t.texels.end(), {1.0f - g, g, 0.0f});
  }
  t.wrap_u = t.wrap_v = TextureWrap::clamp;
  scene.textures.push_back(t);
  scene.camera.eye = Vec3f(0, 90, 0);
  scene.camera.target = Vec3f(0, 0, 0);
  scene.camera.up = Vec3f(0, 0, 1);
  scene.camera.fov_degrees = 10.0f;  // sees z within ±7.9: v from 0.1 to 0.9, along the image's rows
  return scene;
}

Film render_pane(int kind) {
  RenderSettings s;
  s.width = s.height = kPaneImageSizePx;
  s.samples_per_pixel = 64;
  s.seed = 9;
  s.transport.kind = TransportKind::rgb;
  s.path.max_depth = 4;
  return render(floor_behind_pane(kind), s).film;
}

// Green fraction G/(R+G) of each pixel row's mean: the pattern's position.
std::vector<double> row_green_fraction(const Film& f) {
  std::vector<double> out;
  for (int y = 0; y < kPaneImageSizePx; ++y) {
    const test::BlockEstimate e = test::block_estimate(f, 0, y, kPaneImageSizePx, y + 1);
    out.push_back(e.mean.y / (e.mean.x + e.mean.y));
  }
  return out;
}

TEST(ThinPane, DoesNotShiftWhatIsSeenBehindIt) {
  const Film open = render_pane(0), thin = render_pane(1), thick = render_pane(2);
  const auto reference = row_green_fraction(open), through_thin = row_green_fraction(thin),
             through_thick = row_green_fraction(thick);
  // RGB transport, constant η: a path's weight through the pane scales R and G alike, so
  // the fraction is the floor's at the same point; it differs only where a pixel's
  // reflected samples (weight 0) drop part of its footprint. Neighbouring rows differ by
  // about 0.05 here, so 0.01 would detect a shift of a fifth of a pixel.
  double largest_thick_change = 0.0;
  for (int x = 0; x < kPaneImageSizePx; ++x) {
    EXPECT_NEAR(through_thin[static_cast<std::size_t>(x)], reference[static_cast<std::size_t>(x)], 0.01) << "row " << x;
    largest_thick_change = std::max(largest_thick_change, std::abs(through_thick[static_cast<std::size_t>(x)] -
                                                                   reference[static_cast<std::size_t>(x)]));
  }
  EXPECT_GT(largest_thick_change, 0.1) << "a refracting pane must shift the pattern (the check can fail)";
  // Brightness: the camera rays meet the pane at 45° ± 5°, where T' = 1 − R' lies between
  // its values at 40° and 50°; 5σ of the image mean's noise (lobe choice) widens it.
  const test::BlockEstimate o = test::block_estimate(open, 0, 0, kPaneImageSizePx, kPaneImageSizePx),
                            t = test::block_estimate(thin, 0, 0, kPaneImageSizePx, kPaneImageSizePx);
  const auto transmittance = [](double deg) {
    const float cos_i = static_cast<float>(std::cos(deg * std::numbers::pi / 180.0));
    return 1.0 - bsdf::thin_slab_reflectance(bsdf::fresnel_dielectric(cos_i, 1.5f));
  };
  const double ratio = (t.mean.x + t.mean.y) / (o.mean.x + o.mean.y);
  const double sigma = std::sqrt(t.variance.x + t.variance.y) / (o.mean.x + o.mean.y);
  EXPECT_GE(ratio, transmittance(50.0) - 5.0 * sigma);
  EXPECT_LE(ratio, transmittance(40.0) + 5.0 * sigma);
  std::printf("[ pane ] transmitted fraction %.4f ± %.4f (T'(40°) %.4f, T'(45°) %.4f, T'(50°) %.4f); thick shift %.3f\n",
              ratio, sigma, transmittance(40.0), transmittance(45.0), transmittance(50.0), largest_thick_change);
}

}  // namespace
}  // namespace prism
