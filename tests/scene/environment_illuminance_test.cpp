// Illuminance of an environment map on a surface (scene/environment_illuminance.h), against
// closed forms: a uniform sky of luminance L gives π L on any surface (∫ cos θ dω over a
// hemisphere); a sky lit over one hemisphere gives π L facing it, π L / 2 edge-on and 0
// facing away.
#include "prism/scene/environment_illuminance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "prism/scene/environment_mapping.h"

namespace prism {
namespace {


TextureImage constant_map(int width, int height, float value) {
  TextureImage t;
  t.width = width;
  t.height = height;
  t.channels = 3;
  t.texels.assign(static_cast<std::size_t>(width) * height * 3, value);
  return t;
}

// Texels whose centre's direction has z > 0 set to `value`, the others 0.
TextureImage upper_half_map(int n, float value) {
  TextureImage t = constant_map(n, n, 0.0f);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec2f uv((x + 0.5f) / n, (y + 0.5f) / n);
      if (environment_uv_to_direction(EnvironmentMapping::equal_area_octahedral, uv).z > 0.0f)
        for (int c = 0; c < 3; ++c) t.texels[(static_cast<std::size_t>(y) * n + x) * 3 + c] = value;
    }
  return t;
}

TEST(EnvironmentIlluminance, UniformSkyGivesPiTimesItsLuminanceOnAnySurface) {
  // The midpoint rule over texel centres converges as 1/N²: measured relative errors of the
  // octahedral map facing +z: −1.56e-2, −3.91e-3, −9.8e-4, −2.4e-4, −6.1e-5 at N = 16 … 256
  // (exactly −4/N²), so N = 64 is within 1.5e-3 wherever the surface faces.
  const TextureImage octahedral = constant_map(64, 64, 2.0f);
  for (const Vec3f& n : {Vec3f(0, 0, 1), Vec3f(0, 0, -1), Vec3f(1, 0, 0), normalize(Vec3f(1, -2, 3))})
    EXPECT_NEAR(environment_illuminance_lux(octahedral, EnvironmentMapping::equal_area_octahedral, n), 2.0 * std::numbers::pi,
                1.5e-3 * 2.0 * std::numbers::pi)
        << n.x << " " << n.y << " " << n.z;
  // Equirectangular, 128 × 64 (texels weighted by their sin θ solid angle): +4e-4 measured
  // facing +y at 128 × 64 (+1.6e-3 at 64 × 32), so 1e-3.
  const TextureImage latlong = constant_map(128, 64, 2.0f);
  for (const Vec3f& n : {Vec3f(0, 1, 0), Vec3f(0, -1, 0), Vec3f(0, 0, 1)})
    EXPECT_NEAR(environment_illuminance_lux(latlong, EnvironmentMapping::equirectangular, n), 2.0 * std::numbers::pi,
                1e-3 * 2.0 * std::numbers::pi)
        << n.x << " " << n.y << " " << n.z;
}

// Odd: with an even size the horizon (the square's inner diamond) runs through texel
// centres, so the half-lit map would itself lose half a texel all along it. At 65²
// measured +9.5e-4 facing +z and −7.3e-4 edge-on, hence 1.5e-3.
constexpr int kHalfMapSize = 65;

TEST(EnvironmentIlluminance, OnlyTheHemisphereTheSurfaceFacesCounts) {
  const TextureImage half = upper_half_map(kHalfMapSize, 1.0f);
  const auto lux = [&](Vec3f n) { return environment_illuminance_lux(half, EnvironmentMapping::equal_area_octahedral, n); };
  EXPECT_NEAR(lux(Vec3f(0, 0, 1)), std::numbers::pi, 1.5e-3 * std::numbers::pi);
  EXPECT_EQ(lux(Vec3f(0, 0, -1)), 0.0);  // every lit texel is behind the surface
  EXPECT_NEAR(lux(Vec3f(1, 0, 0)), std::numbers::pi / 2.0, 1.5e-3 * std::numbers::pi);  // edge-on: a quarter of the sphere
}

TEST(EnvironmentIlluminance, LuminanceWeightsTheChannelsAsTheTexelsSpace) {
  // A pure green sky: Y = 0.7152 G (Rec.709 / sRGB primaries, D65).
  TextureImage green = constant_map(64, 64, 0.0f);
  for (std::size_t i = 1; i < green.texels.size(); i += 3) green.texels[i] = 1.0f;
  const double lux = environment_illuminance_lux(green, EnvironmentMapping::equal_area_octahedral, Vec3f(0, 0, 1));
  EXPECT_NEAR(lux / environment_illuminance_lux(constant_map(64, 64, 1.0f), EnvironmentMapping::equal_area_octahedral,
                                                Vec3f(0, 0, 1)),
              0.7152, 1e-4);
  // A map whose texels are ACEScg (an OpenEXR kept in its own gamut): AP1's luminance row,
  // Y = 0.2722287168 R + 0.6740817658 G + 0.0536895174 B (SMPTE ST 2065-1 / ACES
  // S-2014-004's AP1 → XYZ matrix), so the same green texels shed 0.6741 of a white's.
  green.texel_space = ColorPickerSpace::acescg;
  TextureImage white = constant_map(64, 64, 1.0f);
  white.texel_space = ColorPickerSpace::acescg;
  EXPECT_NEAR(environment_illuminance_lux(green, EnvironmentMapping::equal_area_octahedral, Vec3f(0, 0, 1)) /
                  environment_illuminance_lux(white, EnvironmentMapping::equal_area_octahedral, Vec3f(0, 0, 1)),
              0.6740817658, 1e-4);
  // Grey images carry luminance in their one channel.
  TextureImage grey;
  grey.width = grey.height = 64;
  grey.channels = 1;
  grey.texels.assign(64 * 64, 1.0f);
  EXPECT_NEAR(environment_illuminance_lux(grey, EnvironmentMapping::equal_area_octahedral, Vec3f(0, 0, 1)), std::numbers::pi,
              1.5e-3 * std::numbers::pi);
}

}  // namespace
}  // namespace prism
