// Issue 4: spectral and RGB transport agree in the mean on a grey world. Every
// reflectance, constant or textured (base colour, metallic-roughness), and every emitter,
// constant or textured, is neutral, and the lights are white: a grey sRGB reflectance
// upsamples to a flat spectrum and a white emitter to an equal-energy one, so a spectral
// film (XYZ relative to E) and an RGB film (sRGB) hold the same three numbers, (Y, Y, Y).
// Each 8×8 block's mean is compared per channel within 5σ of the two renders' noise
// (16 blocks × 3 channels: false-alarm rate below 3e-5 per run).
#include <gtest/gtest.h>

#include <cmath>

#include "prism/render/renderer.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

TextureImage grey_checker(float a, float b, int channels) {
  TextureImage t;
  t.name = "grey-checker";
  t.width = t.height = 4;
  t.channels = channels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const float v = (x + y) % 2 ? a : b;
      for (int c = 0; c < channels; ++c) t.texels.push_back(v);
    }
  return t;
}

TriangleMesh quad(Vec3f corner, Vec3f edge_u, Vec3f edge_v, std::uint32_t material) {
  TriangleMesh m;
  m.positions = {corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v};
  m.indices = {0, 1, 2, 0, 2, 3};  // front face along edge_u × edge_v
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.material = material;
  return m;
}

Scene grey_world() {
  Scene scene;
  scene.name = "grey-world";
  Material floor;  // textured grey base colour (RGB texture of greys)
  floor.base_color = Vec3f(0.9f);
  floor.base_color_texture = 0;
  Material wall;  // constant grey
  wall.base_color = Vec3f(0.5f);
  Material metal;  // glTF metallic-roughness, grey base, textured metallic/roughness
  metal.type = MaterialType::metallic_roughness;
  metal.base_color = Vec3f(0.7f);
  metal.roughness = 0.9f;
  metal.metallic = 1.0f;
  metal.metallic_roughness_texture = 1;
  Material lamp;  // emitter with a grey emission texture
  lamp.base_color = Vec3f(0.0f);
  lamp.emission.color = Vec3f(1.0f);
  lamp.emission.luminance_nits = 40.0f;
  lamp.emission.texture = 2;
  lamp.emission.two_sided = true;
  scene.materials = {floor, wall, metal, lamp};
  scene.textures = {grey_checker(0.2f, 0.8f, 3), grey_checker(0.3f, 1.0f, 3), grey_checker(0.25f, 1.0f, 1)};
  scene.meshes.push_back(quad({-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, 0));     // floor, facing up
  scene.meshes.push_back(quad({-2, 0, -2}, {4, 0, 0}, {0, 3, 0}, 1));     // back wall, facing +z
  scene.meshes.push_back(quad({-2, 0, 2}, {0, 3, 0}, {0, 0, -4}, 2));     // left wall, facing +x
  scene.meshes.push_back(quad({-0.5f, 2.5f, 0.5f}, {1, 0, 0}, {0, 0, -1}, 3));  // lamp
  Light sun;  // white directional light as well
  sun.type = LightType::directional;
  sun.direction = normalize(Vec3f(0.3f, -1.0f, -0.4f));
  sun.intensity = 20.0f;
  scene.lights.push_back(sun);
  scene.camera.eye = Vec3f(0.5f, 1.5f, 4.5f);
  scene.camera.target = Vec3f(-0.3f, 0.8f, 0.0f);
  scene.camera.up = Vec3f(0, 1, 0);
  scene.camera.fov_degrees = 55.0f;
  return scene;
}

TEST(GreyWorld, SpectralAndRgbRendersAgreeInTheMeanWithTextures) {
  const Scene scene = grey_world();
  RenderSettings s;
  s.width = s.height = 32;
  s.samples_per_pixel = 128;
  s.path.max_depth = 4;
  s.seed = 21;
  s.transport.kind = TransportKind::rgb;
  const Film rgb = render(scene, s).film;
  s.seed = 22;
  s.transport = TransportSettings{};  // spectral, the default strategy
  const Film spectral = render(scene, s).film;
  double worst_sigmas = 0.0;
  for (int by = 0; by < 4; ++by)
    for (int bx = 0; bx < 4; ++bx) {
      const auto a = test::block_estimate(rgb, 8 * bx, 8 * by, 8 * bx + 8, 8 * by + 8);
      const auto b = test::block_estimate(spectral, 8 * bx, 8 * by, 8 * bx + 8, 8 * by + 8);
      for (int c = 0; c < 3; ++c) {
        const double sigma = std::sqrt(a.variance[c] + b.variance[c]);
        EXPECT_LE(std::abs(a.mean[c] - b.mean[c]), 5.0 * sigma + 1e-9)
            << "block (" << bx << ", " << by << ") channel " << c << ": RGB " << a.mean[c] << " spectral " << b.mean[c];
        if (sigma > 0.0) worst_sigmas = std::max(worst_sigmas, std::abs(a.mean[c] - b.mean[c]) / sigma);
      }
    }
  const auto a = test::block_estimate(rgb, 0, 0, 32, 32), b = test::block_estimate(spectral, 0, 0, 32, 32);
  std::printf("[ grey-world ] image mean Y: RGB %.5f ± %.5f, spectral %.5f ± %.5f; worst block %.2f sigma\n", a.mean.y,
              std::sqrt(a.variance.y), b.mean.y, std::sqrt(b.variance.y), worst_sigmas);
  EXPECT_GT(a.mean.y, 0.0);
}

}  // namespace
}  // namespace prism
