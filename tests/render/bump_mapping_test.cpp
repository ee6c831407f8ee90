// Bump maps (render/bump_mapping.h): the bumped normal against its definition, and at
// render level a Lambertian floor whose height rises linearly (a ramp texture, which
// bilinear and mip filtering keep linear) under a delta sun: the surface then faces
// (−∂h/∂x, 1, −∂h/∂z) everywhere, and the image's ratio to the flat floor is the cosine
// between the light and that normal, exactly (no random numbers reach a delta light's
// estimate). Each axis, the sign of the slope, mirrored uvs and the scale are checked by a
// direction that fails if any of them is wrong.
#include "prism/render/bump_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/test_scenes.h"

namespace prism {
namespace {


TEST(BumpMapping, FlatHeightKeepsTheNormalAndSlopesTiltIt) {
  const Vec3f n(0, 1, 0), dpdu(2, 0, 0), dpdv(0, 0, 2);
  const Vec3f flat = bumped_normal(n, dpdu, dpdv, 0.0f, 0.0f);
  EXPECT_EQ(flat, n);
  // h = 2u rises by 1 per scene unit along x: the normal is (−1, 1, 0)/√2.
  const Vec3f tilted = bumped_normal(n, dpdu, dpdv, 2.0f, 0.0f);
  EXPECT_NEAR(tilted.x, -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(tilted.y, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(tilted.z, 0.0f, 1e-6f);
  // Position derivatives off the shading plane (a smooth normal over a flat triangle) are
  // projected onto it first: a flat height still gives the shading normal.
  const Vec3f smooth = normalize(Vec3f(0.2f, 1.0f, 0.1f));
  const Vec3f kept = bumped_normal(smooth, dpdu, dpdv, 0.0f, 0.0f);
  EXPECT_NEAR(dot(kept, smooth), 1.0f, 1e-6f);
  // Mirrored uvs (dP/du along −x): still the normal on n's side, tilted the world's way.
  const Vec3f mirrored = bumped_normal(n, Vec3f(-2, 0, 0), dpdv, 2.0f, 0.0f);
  EXPECT_NEAR(mirrored.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_GT(mirrored.y, 0.0f);
  // Degenerate derivatives leave the normal alone.
  EXPECT_EQ(bumped_normal(n, Vec3f(0.0f), dpdv, 0.0f, 0.0f), n);
}

// The sunlit floor (test_scenes.h); with a slope, a 256 × 256 height texture rising along
// u (axis 0) or v (axis 1) by `rise_per_texel` per texel, and a bump scale. The mean of the
// image's red channel.
double floor_red(const Vec3f& toward_light, int slope_axis, float rise_per_texel, float bump_scale,
                 bool mirrored_u = false) {
  Scene scene = test::make_sunlit_uv_floor(toward_light, mirrored_u);
  if (slope_axis >= 0) {
    TextureImage ramp;
    ramp.name = "ramp";
    ramp.width = ramp.height = 256;
    ramp.channels = 1;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x)  // zero mid-texture, where the camera looks: small heights, exact differences
        ramp.texels.push_back(rise_per_texel * static_cast<float>((slope_axis == 0 ? x : y) - 128));
    ramp.wrap_u = ramp.wrap_v = TextureWrap::clamp;
    scene.textures.push_back(ramp);
    scene.materials[0].bump_texture = 0;
    scene.materials[0].bump_scale = bump_scale;
  }
  return test::direct_light_mean_red(scene);
}

// The ramp's texels step by 1/255 (an 8-bit height map's step); this bump scale makes the
// height rise by tan 30° per scene unit: 256 texels span the floor's 200 units.
const float kRise = 1.0f / 255.0f;
const float kScale30 = static_cast<float>(std::tan(std::numbers::pi / 6.0) * 200.0 / 256.0 * 255.0);

Vec3f at_degrees(double degrees, const Vec3f& towards) {  // +y tilted towards a direction in the floor
  const double r = degrees * std::numbers::pi / 180.0;
  return Vec3f(0, static_cast<float>(std::cos(r)), 0) + towards * static_cast<float>(std::sin(r));
}

// Each pixel is ρ/π · E · cos θ; the slope comes from height differences of ≈ 0.6 scene
// units between texel lookups at heights below 1 (the ramp is zero where the camera looks),
// so float rounding moves it by ≈ 1e-6 relative and cos θ by less. 1e-4 is far below what
// a wrong axis, sign or scale does (≥ 0.03).
constexpr double kRelative = 1e-4;

TEST(BumpMapping, LambertianFloorShowsTheCosineToTheBumpedNormal) {
  const double flat = floor_red(Vec3f(0, 1, 0), -1, 0.0f, 1.0f);
  ASSERT_GT(flat, 0.0);
  // Height rising along +x (u) at 30°: the surface faces 30° towards −x.
  EXPECT_NEAR(floor_red(Vec3f(0, 1, 0), 0, kRise, kScale30) / flat, std::cos(std::numbers::pi / 6.0), kRelative);
  EXPECT_NEAR(floor_red(at_degrees(30, Vec3f(-1, 0, 0)), 0, kRise, kScale30) / flat, 1.0, kRelative);
  EXPECT_NEAR(floor_red(at_degrees(30, Vec3f(1, 0, 0)), 0, kRise, kScale30) / flat, 0.5, kRelative);
  // Rising along +z (v): it faces 30° towards −z.
  EXPECT_NEAR(floor_red(at_degrees(30, Vec3f(0, 0, -1)), 1, kRise, kScale30) / flat, 1.0, kRelative);
  EXPECT_NEAR(floor_red(at_degrees(30, Vec3f(0, 0, 1)), 1, kRise, kScale30) / flat, 0.5, kRelative);
  // u running along −x: the height rises towards −x, the surface faces +x.
  EXPECT_NEAR(floor_red(at_degrees(30, Vec3f(1, 0, 0)), 0, kRise, kScale30, true) / flat, 1.0, kRelative);
  // Half the scale, half the slope: tan θ = tan 30° / 2.
  const double half = std::atan(std::tan(std::numbers::pi / 6.0) / 2.0);
  EXPECT_NEAR(floor_red(Vec3f(0, 1, 0), 0, kRise, 0.5f * kScale30) / flat, std::cos(half), kRelative);
}

}  // namespace
}  // namespace prism
