// Environment lights with an equal-area octahedral map (pbrt-v4's image infinite lights):
// the sampler's directions against its solid-angle density by chi-square over the
// map's texels, the density's closed form (a texel's mean luminance under the bilinear
// filter / the map's mean / 4π: the
// Jacobian of an equal-area map is the constant 4π per unit image area) and the
// radiance looked up in the light's own frame.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/core/pcg32.h"
#include "prism/sampling/equal_area_sphere.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/environment_lookup.h"
#include "prism/scene/environment_mapping.h"
#include "prism/scene/flatten_instances.h"
#include "prism/scene/light_sampler.h"
#include "support/chi_square.h"

namespace prism {
namespace {

constexpr int kEnvironmentChiSquareTests = 1;  // test::kAlphaTotal is Šidák-split over these
constexpr int kEnvironmentMapSizePx = 16;

// A square map with uneven colours, one black row and one very bright texel.
TextureImage uneven_map() {
  TextureImage t;
  t.name = "uneven";
  t.width = t.height = kEnvironmentMapSizePx;
  t.channels = 3;
  for (int y = 0; y < kEnvironmentMapSizePx; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x) {
      const float base = y == 3 ? 0.0f : 0.2f + static_cast<float>((7 * x + 3 * y) % 11) / 10.0f;
      const float boost = (x == 12 && y == 9) ? 40.0f : 1.0f;
      t.texels.insert(t.texels.end(), {base * boost, 0.5f * base * boost, (1.0f - 0.04f * x) * base * boost});
    }
  return t;
}

// Map +z → world +y, map +y → world −z, scaled by 2 (the sampler must invert the whole
// linear map, not transpose it).
Transform map_to_world() {
  Transform t;
  const float m[3][3] = {{2, 0, 0}, {0, 0, 2}, {0, -2, 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.m[i][j] = m[i][j];
  return t;
}

Vec3f world_to_map(const Vec3f& w) { return normalize(Vec3f(w.x, -w.z, w.y)); }
Vec3f map_to_world_direction(const Vec3f& m) { return normalize(Vec3f(m.x, m.z, -m.y)); }

Scene octahedral_sky_scene() {
  Scene scene = make_cornell_box();
  scene.materials.back().emission.luminance_nits = 0.0f;  // only the sky emits
  scene.textures.push_back(uneven_map());
  Light sky;
  sky.type = LightType::environment;
  sky.intensity = 3.0f;
  sky.environment_texture = 0;
  sky.environment_mapping = EnvironmentMapping::equal_area_octahedral;
  sky.environment_to_world = map_to_world();
  scene.lights.push_back(sky);
  return scene;
}

double texel_luminance(const TextureImage& t, int x, int y) {
  const Vec3d y_row = color::color_space("srgb").rgb_to_xyz.row(1);
  const float* p = &t.texels[(static_cast<std::size_t>(y) * t.width + x) * 3];
  return dot(y_row, Vec3d(p[0], p[1], p[2]));
}

Vec3f texel_centre_direction(int x, int y) {
  return map_to_world_direction(equal_area_square_to_sphere(Vec2f((x + 0.5f) / kEnvironmentMapSizePx, (y + 0.5f) / kEnvironmentMapSizePx)));
}

// The texels' luminance (given by `luminance(x, y)`) averaged over each texel as the
// bilinearly filtered map has it (environment_lookup.h), and the mean of that over the map.
template <class Luminance>
std::pair<std::vector<float>, double> filtered_texel_means(Luminance luminance) {
  std::vector<float> values;
  for (int y = 0; y < kEnvironmentMapSizePx; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x) values.push_back(static_cast<float>(luminance(x, y)));
  std::vector<float> means;
  double mean = 0.0;
  for (int y = 0; y < kEnvironmentMapSizePx; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x) {
      means.push_back(static_cast<float>(
          environment_texel_mean(values, EnvironmentMapping::equal_area_octahedral, x, y, kEnvironmentMapSizePx, kEnvironmentMapSizePx)));
      mean += means.back() / (kEnvironmentMapSizePx * kEnvironmentMapSizePx);
    }
  return {means, mean};
}

TEST(EnvironmentLight, OctahedralDensityIsLuminanceOverMeanOver4Pi) {
  const Scene scene = octahedral_sky_scene();
  const LightSampler lights(scene, scene_bounds(scene));
  ASSERT_EQ(lights.light_count(), 1u);
  const TextureImage& t = scene.textures[0];
  const auto [texel_means, mean] = filtered_texel_means([&](int x, int y) { return texel_luminance(t, x, y); });
  for (int y = 0; y < kEnvironmentMapSizePx; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x) {
      const auto hits = lights.escaped(texel_centre_direction(x, y));
      ASSERT_EQ(hits.size(), 1u);
      // p_ω = p_uv / 4π with p_uv = the texel's mean luminance / the map's: float rounding
      // of the CDF only.
      const double expected = texel_means[static_cast<std::size_t>(y * kEnvironmentMapSizePx + x)] / mean / (4.0 * std::numbers::pi);
      EXPECT_NEAR(hits[0].pdf, expected, 1e-5 * expected + 1e-9) << x << " " << y;
      // At a texel's centre the radiance is the texel's, times the scale, in the light's
      // frame. The centre's direction maps back to uv within ~1e-6 (float trigonometry),
      // i.e. ~2e-5 texel, which blends in that much of a neighbour differing by up to
      // 3 × 40 × 1.2: 1e-3 absolute.
      const float* p = &t.texels[(static_cast<std::size_t>(y) * kEnvironmentMapSizePx + x) * 3];
      EXPECT_NEAR(hits[0].rgb.x, 3.0f * p[0], 1e-3f);
      EXPECT_NEAR(hits[0].rgb.z, 3.0f * p[2], 1e-3f);
    }
}

// Where the filtered radiance is positive the density is too, even on a black texel beside
// a bright one (the black row 3 next to rows 2 and 4), so light sampling alone reaches it.
TEST(EnvironmentLight, DensityIsPositiveWhereverTheFilteredRadianceIs) {
  const Scene scene = octahedral_sky_scene();
  const LightSampler lights(scene, scene_bounds(scene));
  int positive_on_black_texels = 0;
  for (int y = 2; y <= 4; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x)
      for (float dy : {-0.45f, 0.0f, 0.45f}) {
        const Vec2f uv((x + 0.5f) / kEnvironmentMapSizePx, (y + 0.5f + dy) / kEnvironmentMapSizePx);
        const auto hits = lights.escaped(map_to_world_direction(equal_area_square_to_sphere(uv)));
        ASSERT_EQ(hits.size(), 1u);
        if (hits[0].rgb.y > 0.0f) {
          EXPECT_GT(hits[0].pdf, 0.0f) << x << " " << y << " " << dy;
        }
        if (y == 3 && hits[0].rgb.y > 0.0f) ++positive_on_black_texels;
      }
  EXPECT_GT(positive_on_black_texels, kEnvironmentMapSizePx);  // the filter does reach into the black row
}

// The density follows the luminance of the space the texels are in: an ACEScg map (an
// OpenEXR kept in its own gamut) is weighted by AP1's luminance row (ACES S-2014-004's
// AP1 → XYZ matrix), not Rec.709's, which would put 2 % more density on this map's bluer
// texels relative to its redder ones.
TEST(EnvironmentLight, DensityWeightsTexelsByTheLuminanceOfTheirSpace) {
  Scene scene = octahedral_sky_scene();
  scene.textures[0].texel_space = ColorPickerSpace::acescg;
  const LightSampler lights(scene, scene_bounds(scene));
  const TextureImage& t = scene.textures[0];
  const Vec3d ap1_y(0.2722287168, 0.6740817658, 0.0536895174);
  const auto luminance = [&](int x, int y) {
    const float* p = &t.texels[(static_cast<std::size_t>(y) * t.width + x) * 3];
    return dot(ap1_y, Vec3d(p[0], p[1], p[2]));
  };
  const auto [texel_means, mean] = filtered_texel_means(luminance);
  for (int y = 0; y < kEnvironmentMapSizePx; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x) {
      const auto hits = lights.escaped(texel_centre_direction(x, y));
      ASSERT_EQ(hits.size(), 1u);
      // As above: float rounding of the CDF, and the 10 digits of the published matrix.
      const double expected = texel_means[static_cast<std::size_t>(y * kEnvironmentMapSizePx + x)] / mean / (4.0 * std::numbers::pi);
      EXPECT_NEAR(hits[0].pdf, expected, 1e-5 * expected + 1e-9) << x << " " << y;
    }
}

TEST(EnvironmentLight, OctahedralSamplesFollowTheirDensity) {
  // Bin the sampled directions by the texel they fall in. Each texel of an equal-area map
  // subtends exactly 4π / (W H) sr and the density is constant on it, so its expected
  // count is N · p_ω(texel centre) · 4π / (W H): with p_ω from escaped(), which is what
  // MIS uses. A density that forgot the map's Jacobian is off by 4π everywhere.
  const Scene scene = octahedral_sky_scene();
  const LightSampler lights(scene, scene_bounds(scene));
  constexpr long kSamples = 1'000'000;
  const double texel_solid_angle = 4.0 * std::numbers::pi / (kEnvironmentMapSizePx * kEnvironmentMapSizePx);
  std::vector<double> observed(kEnvironmentMapSizePx * kEnvironmentMapSizePx, 0.0), expected(kEnvironmentMapSizePx * kEnvironmentMapSizePx, 0.0);
  for (int y = 0; y < kEnvironmentMapSizePx; ++y)
    for (int x = 0; x < kEnvironmentMapSizePx; ++x)
      expected[static_cast<std::size_t>(y * kEnvironmentMapSizePx + x)] =
          kSamples * lights.escaped(texel_centre_direction(x, y))[0].pdf * texel_solid_angle;
  Pcg32 rng(31, 37);
  const Vec3f reference(278.0f, 200.0f, 279.0f);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = lights.sample(reference, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_TRUE(s.has_value());
    ASSERT_TRUE(s->has_rgb);
    ASSERT_FALSE(s->is_delta);
    if (i % 1000 == 0) {
      // The density sample() reports is the one escaped() gives MIS (float rounding only).
      const float pdf = lights.escaped(s->wi)[0].pdf;
      ASSERT_NEAR(s->pdf, pdf, 1e-4f * pdf);
    }
    const Vec2f uv = equal_area_sphere_to_square(world_to_map(s->wi));
    const int x = std::clamp(static_cast<int>(uv.x * kEnvironmentMapSizePx), 0, kEnvironmentMapSizePx - 1);
    const int y = std::clamp(static_cast<int>(uv.y * kEnvironmentMapSizePx), 0, kEnvironmentMapSizePx - 1);
    observed[static_cast<std::size_t>(y * kEnvironmentMapSizePx + x)] += 1.0;
  }
  double total = 0.0;
  for (double e : expected) total += e;
  EXPECT_NEAR(total, double(kSamples), 1e-4 * kSamples);  // the density integrates to 1
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kEnvironmentChiSquareTests)) << r.message;
}

TEST(EnvironmentLight, MappingsConvertImageDensityToSolidAngle) {
  // Equirectangular: dω = sin θ dθ dφ = 2π² sin θ du dv; octahedral: 4π.
  EXPECT_FLOAT_EQ(environment_solid_angle_per_uv_area(EnvironmentMapping::equal_area_octahedral, {0.1f, 0.7f}),
                  4.0f * std::numbers::pi_v<float>);
  EXPECT_FLOAT_EQ(environment_solid_angle_per_uv_area(EnvironmentMapping::equirectangular, {0.3f, 0.5f}),
                  2.0f * std::numbers::pi_v<float> * std::numbers::pi_v<float>);
  // Both maps invert themselves.
  for (EnvironmentMapping m : {EnvironmentMapping::equirectangular, EnvironmentMapping::equal_area_octahedral}) {
    const Vec3f d = normalize(Vec3f(0.3f, -0.5f, 0.8f));
    EXPECT_LT(length(environment_uv_to_direction(m, environment_direction_to_uv(m, d)) - d), 1e-5f);
  }
}

}  // namespace
}  // namespace prism
