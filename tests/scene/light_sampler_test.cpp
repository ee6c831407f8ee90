// Light sampling: uniform points on area lights with the right solid-angle density,
// delta lights, spot falloff, sun discs, and selection proportional to power.
#include "prism/scene/light_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "prism/core/frame.h"
#include "prism/core/pcg32.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/emission.h"
#include "prism/scene/flatten_instances.h"
#include "support/chi_square.h"

namespace prism {
namespace {

constexpr int kLightSamplerChiSquareTests = 5;  // test::kAlphaTotal is Šidák-split over these

TEST(LightSampler, AreaLightPointsAreUniformWithSolidAngleDensity) {
  // Cornell light: a 130 × 105 mm rectangle at constant y, seen from the floor below it.
  // Area sampling (the solid-angle strategies have their own tests in
  // triangle_light_sampling_test.cpp), with and without reusing the selection sample.
  const Scene scene = make_cornell_box();
  for (const bool reuse : {false, true}) {
    const LightSampler lights(scene, scene_bounds(scene), {TriangleLightSampling::area, reuse});
    ASSERT_EQ(lights.light_count(), 2u);
    const Vec3f reference(278.0f, 0.0f, 279.0f);
    constexpr int kGrid = 16;
    constexpr long kSamples = 400'000;
    std::vector<double> observed(kGrid * kGrid, 0.0), expected(kGrid * kGrid, double(kSamples) / (kGrid * kGrid));
    Pcg32 rng(5, 6);
    for (long i = 0; i < kSamples; ++i) {
      const auto s = lights.sample(reference, rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
      ASSERT_TRUE(s.has_value());
      ASSERT_FALSE(s->is_delta);
      ASSERT_LT(s->normal.y, -0.999f);
      // p_ω = r² / (cos θ_light · A_total): both triangles are chosen in proportion to area.
      const float d2 = length_squared(s->position - reference);
      const float cos_light = -dot(s->normal, s->wi);
      ASSERT_NEAR(s->pdf, d2 / (cos_light * 130.0f * 105.0f), 1e-4f * s->pdf);
      const int ix = std::clamp(static_cast<int>((s->position.x - 213.0f) / 130.0f * kGrid), 0, kGrid - 1);
      const int iz = std::clamp(static_cast<int>((s->position.z - 227.0f) / 105.0f * kGrid), 0, kGrid - 1);
      observed[static_cast<std::size_t>(iz * kGrid + ix)] += 1.0;
    }
    const auto r = test::chi_square_test(observed, expected);
    EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kLightSamplerChiSquareTests)) << "reuse " << reuse << ": " << r.message;
  }
}

TEST(LightSampler, ReusedSelectionSampleIsTheRescaledRemainder) {
  // The Cornell light's two triangles have equal power: pmf 1/2 each, so with reuse
  // u_point.x = x picks triangle ⌊2x⌋ and samples it with u.x = 2x mod 1, exactly (powers
  // of two): the same sample as u_select = x and u_point = (2x mod 1, y) without reuse.
  const Scene scene = make_cornell_box();
  const LightSampler reuse(scene, scene_bounds(scene), {TriangleLightSampling::solid_angle_cosine, true});
  const LightSampler plain(scene, scene_bounds(scene), {TriangleLightSampling::solid_angle_cosine, false});
  const Vec3f reference(278.0f, 0.0f, 279.0f), normal(0, 1, 0);
  for (const float x : {0.0f, 0.1f, 0.3f, 0.49f, 0.5f, 0.62f, 0.9f, 0.99f}) {
    const float rescaled = x < 0.5f ? 2.0f * x : 2.0f * x - 1.0f;
    const auto a = reuse.sample(reference, 0.77f, Vec2f(x, 0.4f), normal);
    const auto b = plain.sample(reference, x, Vec2f(rescaled, 0.4f), normal);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->position, b->position) << x;
    EXPECT_EQ(a->pdf, b->pdf) << x;
  }
  // An emitter chosen with probability below kMinReusedSelectionPmf takes u_select as its
  // u.x instead: a point light 10⁴ times the light's power leaves each triangle < 1/256.
  Scene bright = make_cornell_box();
  Light point;
  point.type = LightType::point;
  point.position = Vec3f(100, 300, 100);
  point.intensity = 1e4f * scene.materials.back().emission.luminance_nits * 130.0f * 105.0f / 4.0f;
  bright.lights.push_back(point);
  const LightSampler reuse_bright(bright, scene_bounds(bright), {TriangleLightSampling::solid_angle_cosine, true});
  const LightSampler plain_bright(bright, scene_bounds(bright), {TriangleLightSampling::solid_angle_cosine, false});
  const float x = 1e-5f;  // inside the first triangle's interval [0, ~5e-5)
  const auto a = reuse_bright.sample(reference, 0.3f, Vec2f(x, 0.4f), normal);
  const auto b = plain_bright.sample(reference, x, Vec2f(0.3f, 0.4f), normal);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->position, b->position);
  EXPECT_EQ(a->pdf, b->pdf);

  // uses_selection_number() says when u_select is read at all (the integrator then skips
  // drawing it): never with reuse and every pmf ≥ 1/256 — any u_select gives the same
  // sample — otherwise yes.
  EXPECT_FALSE(reuse.uses_selection_number());
  EXPECT_TRUE(plain.uses_selection_number());
  EXPECT_TRUE(reuse_bright.uses_selection_number());
  for (const float x : {0.0f, 0.3f, 0.77f}) {
    const auto u0 = reuse.sample(reference, 0.0f, Vec2f(x, 0.4f), normal);
    const auto u1 = reuse.sample(reference, 0.999f, Vec2f(x, 0.4f), normal);
    ASSERT_TRUE(u0 && u1);
    EXPECT_EQ(u0->position, u1->position) << x;
  }
}

TEST(LightSampler, TrianglePdfMatchesSampling) {
  const Scene scene = make_cornell_box();
  const LightSampler lights(scene, scene_bounds(scene), {TriangleLightSampling::area, false});
  const auto light_mesh = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  const Vec3f reference(100.0f, 50.0f, 300.0f), on_light(278.0f, 548.3f, 279.0f);
  const Vec3f wi = normalize(on_light - reference);
  const float cos_light = -dot(Vec3f(0, -1, 0), wi);
  const float expected = length_squared(on_light - reference) / (cos_light * 130.0f * 105.0f);
  EXPECT_NEAR(lights.pdf_triangle(light_mesh, 1, reference, on_light), expected, 1e-4f * expected);
  EXPECT_EQ(lights.pdf_triangle(0, 0, reference, on_light), 0.0f);  // the floor emits nothing
  // Above the light (behind its emitting side) nothing can be sampled.
  EXPECT_FALSE(lights.sample(Vec3f(278, 600, 279), 0.5f, Vec2f(0.5f, 0.5f)).has_value());
}

Scene scene_with(const Light& light) {
  Scene scene = make_cornell_box();
  scene.materials.back().emission.luminance_nits = 0.0f;  // only the test light emits
  scene.lights.push_back(light);
  return scene;
}

TEST(LightSampler, PointLightIsDeltaWithInverseSquareFalloff) {
  Light point;
  point.type = LightType::point;
  point.position = Vec3f(200, 400, 200);
  point.intensity = 100.0f;
  const Scene scene = scene_with(point);
  const LightSampler lights(scene, scene_bounds(scene));
  ASSERT_EQ(lights.light_count(), 1u);
  const Vec3f reference(200, 0, 200);
  const auto s = lights.sample(reference, 0.3f, Vec2f(0.1f, 0.9f));
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->is_delta);
  EXPECT_FLOAT_EQ(s->pdf, 1.0f);
  EXPECT_FLOAT_EQ(s->distance, 400.0f);
  EXPECT_FLOAT_EQ(s->scale, 1.0f / (400.0f * 400.0f));
  EXPECT_EQ(s->emitter, static_cast<std::uint32_t>(scene.materials.size()));
}

TEST(LightSampler, SpotLightFallsOffBetweenItsCones) {
  Light spot;
  spot.type = LightType::spot;
  spot.position = Vec3f(0, 100, 0);
  spot.direction = Vec3f(0, -1, 0);
  spot.spot_inner_angle_degrees = 20.0f;
  spot.spot_outer_angle_degrees = 40.0f;
  const Scene scene = scene_with(spot);
  const LightSampler lights(scene, scene_bounds(scene));
  const auto at_angle = [&](float degrees) {
    const float t = std::tan(degrees * std::numbers::pi_v<float> / 180.0f);
    return lights.sample(Vec3f(100.0f * t, 0, 0), 0.5f, Vec2f(0.5f, 0.5f));
  };
  const auto inside = at_angle(10.0f);
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->scale * length_squared(inside->position - Vec3f(100.0f * std::tan(10.0f * std::numbers::pi_v<float> / 180.0f), 0, 0)), 1.0f, 1e-4f);
  const auto middle = at_angle(30.0f);
  ASSERT_TRUE(middle.has_value());
  const float d2 = length_squared(middle->position - Vec3f(100.0f * std::tan(30.0f * std::numbers::pi_v<float> / 180.0f), 0, 0));
  EXPECT_GT(middle->scale * d2, 0.0f);
  EXPECT_LT(middle->scale * d2, 1.0f);
  EXPECT_FALSE(at_angle(50.0f).has_value());
}

TEST(LightSampler, SunDiscDirectionsAreUniformInTheCone) {
  Light sun;
  sun.type = LightType::directional;
  sun.direction = normalize(Vec3f(0.3f, -1.0f, 0.2f));
  sun.angular_diameter_degrees = 20.0f;  // large, so the histogram resolves the cone
  sun.intensity = 1000.0f;
  const Scene scene = scene_with(sun);
  const LightSampler lights(scene, scene_bounds(scene));
  const float cos_max = std::cos(10.0f * std::numbers::pi_v<float> / 180.0f);
  // Uniform in the cone ⇔ (1 − cos θ)/(1 − cos θmax) and φ/2π uniform on [0, 1)² in the
  // cone's own frame (the pdf is constant inside and the map is measure-preserving), so
  // histogram those: no bin straddles the cone's edge.
  const Frame frame = Frame::from_normal(-sun.direction);
  constexpr int kGrid = 20;
  constexpr long kSamples = 400'000;
  std::vector<double> observed(kGrid * kGrid, 0.0), expected(kGrid * kGrid, double(kSamples) / (kGrid * kGrid));
  Pcg32 rng(3, 8);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = lights.sample(Vec3f(0.0f), rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_TRUE(s.has_value());
    ASSERT_NEAR(s->pdf, 1.0f / (2.0f * std::numbers::pi_v<float> * (1.0f - cos_max)), 1e-3f);
    const Vec3f d = frame.to_local(s->wi);
    ASSERT_GE(d.z, cos_max - 1e-5f);
    double phi = std::atan2(double(d.y), double(d.x));
    if (phi < 0.0) phi += 2.0 * std::numbers::pi;
    const int a = std::clamp(static_cast<int>((1.0 - d.z) / (1.0 - cos_max) * kGrid), 0, kGrid - 1);
    const int b = std::clamp(static_cast<int>(phi / (2.0 * std::numbers::pi) * kGrid), 0, kGrid - 1);
    observed[static_cast<std::size_t>(a * kGrid + b)] += 1.0;
  }
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kLightSamplerChiSquareTests)) << r.message;
  // Escaping rays inside the disc see radiance E / (π sin²θ) with the sampling density.
  const auto hits = lights.escaped(-sun.direction);
  ASSERT_EQ(hits.size(), 1u);
  // Both sides compute 1 − cos² in float, which cancels: a relative rounding error of a few ε
  // in cos² grows by 1/(1 − cos²) (33× for this 10° disc), so allow 4 ε of that size.
  const float expected_scale = 1.0f / (std::numbers::pi_v<float> * (1.0f - cos_max * cos_max));
  EXPECT_NEAR(hits[0].scale, expected_scale,
              expected_scale * 4.0f * std::numeric_limits<float>::epsilon() / (1.0f - cos_max * cos_max));
  EXPECT_TRUE(lights.escaped(sun.direction).empty());
}

TEST(LightSampler, SelectionIsProportionalToPower) {
  // Cornell light (Φ = π L A) and a point light (Φ = 4π I) chosen in proportion.
  Scene scene = make_cornell_box();
  Light point;
  point.type = LightType::point;
  point.position = Vec3f(100, 300, 100);
  point.intensity = 5000.0f;
  scene.lights.push_back(point);
  const LightSampler lights(scene, scene_bounds(scene));
  const double area_power = std::numbers::pi * scene.materials.back().emission.luminance_nits * 130.0 * 105.0;
  const double point_power = 4.0 * std::numbers::pi * 5000.0;
  const double p_point = point_power / (area_power + point_power);
  constexpr long kSamples = 200'000;
  std::vector<double> observed(2, 0.0);
  Pcg32 rng(1, 9);
  const auto point_id = static_cast<std::uint32_t>(scene.materials.size());
  for (long i = 0; i < kSamples; ++i) {
    const auto s = lights.sample(Vec3f(278, 10, 279), rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_TRUE(s.has_value());
    observed[s->emitter == point_id ? 1 : 0] += 1.0;
  }
  const std::vector<double> expected = {kSamples * (1.0 - p_point), kSamples * p_point};
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kLightSamplerChiSquareTests)) << r.message;
}

// A textured emitter's triangles are chosen in proportion to their power estimate: the
// mean weight of their uv footprint plus 1 % of the texture's mean over its texels (the
// floor that keeps dark triangles selectable). Two equal triangles, one mapped onto a
// white texel and one onto a black one (clamped 2×1 texture, mean 0.5): weights
// 1 + 0.005 and 0 + 0.005, so the dark one is chosen with probability 0.005 / 1.01.
TEST(LightSampler, TexturedEmitterSelectionHasTheTextureMeanFloor) {
  Scene scene;
  Material emitter;
  emitter.emission.color = Vec3f(1.0f);
  emitter.emission.luminance_nits = 1.0f;
  emitter.emission.texture = 0;
  scene.materials.push_back(emitter);
  TextureImage t;
  t.width = 2;
  t.height = 1;
  t.channels = 3;
  t.texels = {1, 1, 1, 0, 0, 0};
  t.wrap_u = t.wrap_v = TextureWrap::clamp;
  scene.textures.push_back(t);
  TriangleMesh mesh;  // two unit right triangles in the plane y = 0, facing +y
  mesh.positions = {{-2, 0, 0}, {-2, 0, 1}, {-1, 0, 0}, {1, 0, 0}, {1, 0, 1}, {2, 0, 0}};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  // Bright triangle within u ≤ 0.2 (texel 0 alone), dark one within u ≥ 0.8 (texel 1).
  mesh.uvs = {{0.0f, 0.5f}, {0.1f, 0.5f}, {0.2f, 0.5f}, {0.8f, 0.5f}, {0.9f, 0.5f}, {1.0f, 0.5f}};
  scene.meshes.push_back(mesh);
  const LightSampler lights(scene, scene_bounds(scene));
  const double p_dark = 0.005 / 1.01;
  constexpr long kSamples = 400'000;
  std::vector<double> observed(2, 0.0);
  Pcg32 rng(3, 7);
  for (long i = 0; i < kSamples; ++i) {
    const auto s = lights.sample(Vec3f(0, 5, 0.3f), rng.next_float(), Vec2f(rng.next_float(), rng.next_float()));
    ASSERT_TRUE(s.has_value());
    observed[s->position.x > 0.0f ? 1 : 0] += 1.0;
  }
  const std::vector<double> expected = {kSamples * (1.0 - p_dark), kSamples * p_dark};
  const auto r = test::chi_square_test(observed, expected);
  EXPECT_GT(r.p_value, test::sidak_alpha(test::kAlphaTotal, kLightSamplerChiSquareTests)) << r.message;
}

// Four emissive triangles in the plane y = 0 with small uv footprints in different parts of
// `texture`, on a lamp of an unequal colour (so a swapped channel shows) in `space`.
LightSampler textured_lamp_lights(const TextureImage& texture, ColorPickerSpace space = ColorPickerSpace::srgb) {
  Scene scene;
  Material emitter;
  emitter.emission.color = Vec3f(0.9f, 0.5f, 0.2f);
  emitter.emission.color_space = space;
  emitter.emission.luminance_nits = 3.0f;
  emitter.emission.texture = 0;
  scene.materials.push_back(emitter);
  scene.textures.push_back(texture);
  TriangleMesh mesh;
  for (int t = 0; t < 4; ++t) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{float(t), 0, 0}, {float(t), 0, 1}, {float(t) + 1, 0, 0}});
    const float u = 0.1f + 0.23f * static_cast<float>(t), v = 0.7f - 0.17f * static_cast<float>(t);
    mesh.uvs.insert(mesh.uvs.end(), {{u, v}, {u + 0.05f, v}, {u, v + 0.04f}});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
  }
  scene.meshes.push_back(mesh);
  return LightSampler(scene, scene_bounds(scene));
}

// An 8-bit emission texture weighs its triangles as the floats it decodes to: the
// texture's mean (the selection floor) is summed from per-code tables for codes and from
// the texels for floats, and every triangle's probability must come out the same float,
// for grey, grey + alpha, RGB and RGBA images under a coloured emission (a table of the
// wrong channel or encoding moves the mean, and with it every probability). The mean's
// last bits in double are rounded away in the float probabilities; that they agree too is
// by construction (the same products and sums, light_sampler.cpp).
TEST(LightSampler, CodedEmissionTexturesWeighTrianglesAsTheirDecodedFloats) {
  for (const TextureEncoding encoding : {TextureEncoding::srgb, TextureEncoding::linear})
    for (int channels = 1; channels <= 4; ++channels) {
      TextureImage coded;
      coded.width = 23;
      coded.height = 17;
      coded.channels = channels;
      coded.encoding = encoding;
      Pcg32 rng(11, static_cast<std::uint64_t>(channels));
      for (int i = 0; i < coded.width * coded.height * channels; ++i)
        coded.codes.push_back(static_cast<std::uint8_t>(rng.next_u32() >> 24));
      TextureImage floats = coded;
      floats.texels = coded.linear_values();
      floats.codes.clear();
      ASSERT_TRUE(coded.has_codes());
      ASSERT_FALSE(floats.has_codes());

      const LightSampler from_codes = textured_lamp_lights(coded), from_floats = textured_lamp_lights(floats);
      for (std::uint32_t t = 0; t < 4; ++t) {
        const Vec3f on_triangle(static_cast<float>(t) + 0.3f, 0.0f, 0.3f), above(1.5f, 4.0f, 0.5f);
        const float pdf = from_codes.pdf_triangle(0, t, above, on_triangle);
        EXPECT_GT(pdf, 0.0f);
        EXPECT_EQ(pdf, from_floats.pdf_triangle(0, t, above, on_triangle))
            << "encoding " << static_cast<int>(encoding) << " channels " << channels << " triangle " << t;
      }
    }
}

// A texture in another space than its lamp's colour (a Rec.709 PNG on an ACEScg lamp)
// weighs its triangles as its texels converted to the lamp's space, where they multiply the
// colour (scene/emission.h): the same probabilities as the texture converted beforehand and
// held in ACEScg. Without the conversion the Rec.709 numbers would be weighed as ACEScg
// ones, whose luminance row differs (blue 0.054 against 0.072).
TEST(LightSampler, EmissionTexturesInAnotherSpaceWeighTrianglesAsTheirConvertedTexels) {
  TextureImage coded;
  coded.width = 19;
  coded.height = 13;
  coded.channels = 3;
  coded.encoding = TextureEncoding::srgb;
  Pcg32 rng(5, 9);
  for (int i = 0; i < coded.width * coded.height * 3; ++i) coded.codes.push_back(static_cast<std::uint8_t>(rng.next_u32() >> 24));
  TextureImage converted = coded;
  converted.codes.clear();
  converted.texel_space = ColorPickerSpace::acescg;
  const std::vector<float> values = coded.linear_values();
  const Mat3& to_acescg = picker_space_conversion(ColorPickerSpace::srgb, ColorPickerSpace::acescg);
  for (std::size_t i = 0; i < values.size(); i += 3) {
    const Vec3d v = to_acescg * Vec3d(values[i], values[i + 1], values[i + 2]);
    converted.texels.insert(converted.texels.end(), {float(v.x), float(v.y), float(v.z)});
  }
  const LightSampler from_rec709 = textured_lamp_lights(coded, ColorPickerSpace::acescg),
                     from_acescg = textured_lamp_lights(converted, ColorPickerSpace::acescg);
  for (std::uint32_t t = 0; t < 4; ++t) {
    const Vec3f on_triangle(static_cast<float>(t) + 0.3f, 0.0f, 0.3f), above(1.5f, 4.0f, 0.5f);
    const float expected = from_acescg.pdf_triangle(0, t, above, on_triangle);
    // The converted texels were rounded to float once (1e-7 relative) and bilinear filtering
    // rounds again: 1e-5 relative.
    EXPECT_NEAR(from_rec709.pdf_triangle(0, t, above, on_triangle), expected, 1e-5 * expected) << "triangle " << t;
  }
}

}  // namespace
}  // namespace prism
