// pbrt-v4 image infinite lights: read with pbrt-v4's equal-area octahedral mapping in the
// light's own frame (its CTM), square images only, and rendered with the orientation
// pbrt-v4 gives them.
//
// The convention (source: pbrt-v4 book, §12.5.2 "Image Infinite Lights", ImageInfiniteLight::Le:
// wLight = renderFromLight⁻¹(ray.d), uv = EqualAreaSphereToSquare(wLight), nearest texel; and
// §3.8.3 "Equal-Area Mapping": the square's centre is +z, x follows u and y follows v, pixel
// (0, 0) at the image's top left). A map lit only in the octant x, y, z > 0 of the light's
// frame therefore lights that octant of the world when the CTM is the identity.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "loader_test_files.h"
#include "prism/core/error.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "prism/render/renderer.h"
#include "prism/scene/environment_illuminance.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "support/exr_rec709.h"
#include "support/film_statistics.h"

namespace prism::loaders {
namespace {

using test::kRec709;  // support/exr_rec709.h
constexpr int kSize = 32;

// 1 where the texel centre's direction is in the octant x, y, z > 0, i.e. the triangle
// u, v > 1/2, (2u − 1) + (2v − 1) < 1 of the square; 0 elsewhere.
void write_octant_map(const std::filesystem::path& file) {
  ImageRgbF image{kSize, kSize, std::vector<float>(kSize * kSize * 3, 0.0f)};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float a = 2.0f * (x + 0.5f) / kSize - 1.0f, b = 2.0f * (y + 0.5f) / kSize - 1.0f;
      if (a > 0.0f && b > 0.0f && a + b < 1.0f)
        for (int c = 0; c < 3; ++c) image.rgb[(static_cast<std::size_t>(y) * kSize + x) * 3 + c] = 1.0f;
    }
  write_exr(file, image, kRec709);
}

std::string scene_text(std::string_view light_transform) {
  return std::string(R"(Scale -1 1 1
LookAt 0 0 6  0 0 0  0 1 0
Camera "perspective" "float fov" 30
Film "rgb" "integer xresolution" 32 "integer yresolution" 32
WorldBegin
AttributeBegin
)") + std::string(light_transform) +
         R"(
LightSource "infinite" "string filename" "octant.exr" "float scale" 2
AttributeEnd
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "sphere" "float radius" 1
)";
}

// Radiance (luminance scale) the sky shows in world direction d.
float sky(const Scene& scene, Vec3f d) {
  const LightSampler lights(scene, scene_bounds(scene));
  const auto hits = lights.escaped(normalize(d));
  return hits.empty() ? -1.0f : hits[0].rgb.y;
}

TEST(PbrtInfiniteLight, ImageIsEqualAreaOctahedralInTheLightFrame) {
  test::ScratchFolder dir;
  write_octant_map(dir / "octant.exr");
  const Scene s = load_pbrt_scene(dir.write("sky.pbrt", scene_text("")));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].environment_mapping, EnvironmentMapping::equal_area_octahedral);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("equirectangular"), std::string::npos) << w;
  // Well inside the octant (away from the staircase of texels along its edges).
  EXPECT_FLOAT_EQ(sky(s, {1, 1, 1}), 2.0f);
  EXPECT_FLOAT_EQ(sky(s, {-1, 1, 1}), 0.0f);
  EXPECT_FLOAT_EQ(sky(s, {1, -1, 1}), 0.0f);
  EXPECT_FLOAT_EQ(sky(s, {1, 1, -1}), 0.0f);
  // The CTM turns the map: Rotate 90° about z takes x to y and y to −x, so the lit octant
  // becomes x < 0, y > 0, z > 0.
  const Scene r = load_pbrt_scene(dir.write("rotated.pbrt", scene_text("Rotate 90 0 0 1")));
  EXPECT_FLOAT_EQ(sky(r, {-1, 1, 1}), 2.0f);
  EXPECT_FLOAT_EQ(sky(r, {1, 1, 1}), 0.0f);
  EXPECT_FLOAT_EQ(sky(r, {1, -1, 1}), 0.0f);
}

TEST(PbrtInfiniteLight, RendersTheLitOctantOnTheExpectedSideOfASphere) {
  // The camera at +z looks at a diffuse unit sphere; `Scale -1 1 1` makes the image the
  // one pbrt-v4 renders: world +x to the right, +y up. The sky is lit only towards
  // +x, +y, +z, so the sphere's upper-right quarter is the brightest and its lower-left
  // the darkest. Irradiance from the octant at the blocks' middle normals (±0.45, ±0.45,
  // 0.77), by numerical integration: 1.32 upper right, 0.64 upper left and lower right,
  // 0.19 lower left. Measured over the blocks (normals 0.2–0.7 off axis, 64 spp): ratios of
  // 1.84 (upper right to upper left and to lower right) and 2.55 (those to lower left);
  // a map mirrored in x or y turns the first below 1, so 1.5 separates right from wrong
  // with room for noise.
  test::ScratchFolder dir;
  write_octant_map(dir / "octant.exr");
  const Scene s = load_pbrt_scene(dir.write("sky.pbrt", scene_text("")));
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.samples_per_pixel = 64;
  settings.seed = 5;
  settings.path.max_depth = 1;
  const Film film = render(s, settings).film;
  // Blocks 2–7 pixels off the centre (the sphere's image has a radius of about 10 pixels).
  const double upper_right = test::block_estimate(film, 18, 9, 23, 14).mean.y;
  const double upper_left = test::block_estimate(film, 9, 9, 14, 14).mean.y;
  const double lower_right = test::block_estimate(film, 18, 18, 23, 23).mean.y;
  const double lower_left = test::block_estimate(film, 9, 18, 14, 23).mean.y;
  EXPECT_GT(upper_right, 1.5 * upper_left);
  EXPECT_GT(upper_right, 1.5 * lower_right);
  EXPECT_GT(upper_left, 1.5 * lower_left);
  EXPECT_GT(lower_right, 1.5 * lower_left);
}

// "illuminance" (lux) scales the sky so that a surface facing the light frame's +z receives
// that much light from it, times "scale" (pbrt-v4's ImageInfiniteLight and uniform
// infinite light). A uniform sky of luminance L gives π L lux (∫ cos θ dω over the
// hemisphere), so a constant map of 1 scaled for E lux has luminance E / π.
TEST(PbrtInfiniteLight, IlluminanceScalesTheSkyForASurfaceFacingPlusZ) {
  test::ScratchFolder dir;
  write_exr(dir / "constant.exr", ImageRgbF{kSize, kSize, std::vector<float>(kSize * kSize * 3, 1.0f)}, kRec709);
  const Scene s = load_pbrt_scene(dir.write("sky.pbrt", R"(WorldBegin
LightSource "infinite" "string filename" "constant.exr" "float scale" 2 "float illuminance" 1000
Shape "sphere"
)"));
  ASSERT_EQ(s.lights.size(), 1u);
  const TextureImage& map = s.textures[static_cast<std::size_t>(s.lights[0].environment_texture)];
  const double map_lux = environment_illuminance_lux(map, EnvironmentMapping::equal_area_octahedral, Vec3f(0, 0, 1));
  // The midpoint rule over N² equal-area texels falls short of π by 4/N² relative
  // (environment_illuminance_test: −3.9e-3 at N = 32), so 5e-3; the whole sphere, or no
  // cosine, would give 2π.
  EXPECT_NEAR(map_lux, std::numbers::pi, 5e-3 * std::numbers::pi);
  EXPECT_NEAR(s.lights[0].intensity, 2.0 * 1000.0 / map_lux, 1e-6 * s.lights[0].intensity);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("illuminance"), std::string::npos) << w;
  // Light only below the horizon: no scale gives the asked illuminance.
  ImageRgbF below{kSize, kSize, std::vector<float>(kSize * kSize * 3, 0.0f)};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float a = 2.0f * (x + 0.5f) / kSize - 1.0f, b = 2.0f * (y + 0.5f) / kSize - 1.0f;
      if (std::abs(a) + std::abs(b) > 1.0f)  // the square's corners: z < 0
        for (int c = 0; c < 3; ++c) below.rgb[(static_cast<std::size_t>(y) * kSize + x) * 3 + c] = 1.0f;
    }
  write_exr(dir / "below.exr", below, kRec709);
  const std::string error = test::error_of<SceneError>([&] {
    load_pbrt_scene(dir.write("below.pbrt", R"(WorldBegin
LightSource "infinite" "string filename" "below.exr" "float illuminance" 1000
Shape "sphere"
)"));
  });
  EXPECT_NE(error.find("below.pbrt:2"), std::string::npos) << error;
  EXPECT_NE(error.find("illuminance"), std::string::npos) << error;
  // A uniform "L" sky: its luminance becomes scale · E / π, its colour the chromaticity.
  const Scene u = load_pbrt_scene(dir.write("uniform.pbrt", R"(WorldBegin
LightSource "infinite" "rgb L" [0.2 0.5 0.9] "float scale" 3 "float illuminance" 100
Shape "sphere"
)"));
  ASSERT_EQ(u.lights.size(), 1u);
  EXPECT_NEAR(u.lights[0].intensity, 3.0 * 100.0 / std::numbers::pi, 1e-4);
  // Negative illuminance is an error at its parameter.
  const std::string negative = test::error_of<SceneError>([&] {
    load_pbrt_scene(dir.write("negative.pbrt", R"(WorldBegin
LightSource "infinite" "rgb L" [1 1 1] "float illuminance" -5
)"));
  });
  EXPECT_NE(negative.find("negative.pbrt:2"), std::string::npos) << negative;
}

TEST(PbrtInfiniteLight, NegativeScaleOfAnImageSkyIsAnError) {
  // A negative scale would make the sky emit negative radiance.
  test::ScratchFolder dir;
  write_octant_map(dir / "octant.exr");
  const std::string error = test::error_of<SceneError>([&] {
    load_pbrt_scene(dir.write("sky.pbrt", R"(WorldBegin
LightSource "infinite" "string filename" "octant.exr" "float scale" -2
Shape "sphere"
)"));
  });
  EXPECT_NE(error.find("sky.pbrt:2"), std::string::npos) << error;
  EXPECT_NE(error.find("negative"), std::string::npos) << error;
}

TEST(PbrtInfiniteLight, NonSquareImagesAreRefused) {
  test::ScratchFolder dir;
  write_exr(dir / "octant.exr", ImageRgbF{8, 4, std::vector<float>(8 * 4 * 3, 1.0f)}, kRec709);
  const std::string error =
      test::error_of<SceneError>([&] { load_pbrt_scene(dir.write("sky.pbrt", scene_text(""))); });
  EXPECT_NE(error.find("sky.pbrt:8"), std::string::npos) << error;
  EXPECT_NE(error.find("square"), std::string::npos) << error;
}

TEST(PbrtInfiniteLight, PngMapsAreSrgbEncodedAsPbrtReadsThem) {
  // pbrt-v4's Image::Read decodes an 8-bit PNG with the sRGB curve when no encoding is
  // asked for, as its infinite light does: code 128 is linear 0.21586 (IEC 61966-2-1).
  test::ScratchFolder dir;
  write_png(dir / "grey.png", EncodedImage{2, 2, 3, 8, std::vector<std::uint16_t>(12, 128)});
  const Scene s = load_pbrt_scene(dir.write("sky.pbrt", R"(WorldBegin
LightSource "infinite" "string filename" "grey.png" "float scale" 2
Shape "sphere"
)"));
  const double linear = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);
  EXPECT_NEAR(sky(s, {0, 0, 1}), 2.0 * linear, 1e-6);
}

}  // namespace
}  // namespace prism::loaders
