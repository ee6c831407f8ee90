// Material textures beyond base colour, at render level: glTF's metallic-roughness
// texture (G = roughness, B = metallic) must give each textured region the image its
// constants would, and emission textures must scale radiance as texel × factor × strength
// and stay consistent between light sampling and BSDF sampling.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/render/color_context.h"
#include "prism/render/renderer.h"
#include "prism/scene/emission.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using Estimate = test::BlockEstimate;

Estimate texture_block(const Film& film, int x0, int y0, int x1, int y1) { return test::block_estimate(film, x0, y0, x1, y1); }
Estimate texture_whole_film(const Film& film) { return texture_block(film, 0, 0, film.width(), film.height()); }

TransportSettings rgb_transport() {
  TransportSettings t;
  t.kind = TransportKind::rgb;
  return t;
}

TransportSettings spectral_transport() {
  TransportSettings t;
  t.wavelengths = 4;
  t.wavelength_strategy = color::WavelengthStrategy::hero;
  return t;
}

RenderSettings texture_settings_for(const TransportSettings& transport, int size, int spp, std::uint64_t seed) {
  RenderSettings s;
  s.width = s.height = size;
  s.samples_per_pixel = spp;
  s.seed = seed;
  s.transport = transport;
  return s;
}

// A 16×1 clamped texture: texels 0–7 (u < ½) are `left`, 8–15 are `right`.
TextureImage two_halves(const Vec3f& left, const Vec3f& right) {
  TextureImage t;
  t.name = "halves";
  t.width = 16;
  t.height = 1;
  t.channels = 3;
  for (int i = 0; i < 16; ++i) {
    const Vec3f& c = i < 8 ? left : right;
    t.texels.insert(t.texels.end(), {c.x, c.y, c.z});
  }
  t.wrap_u = t.wrap_v = TextureWrap::clamp;
  return t;
}

// A 200×200 floor (front face up, uv 0–1 along x and z) seen from 90 units straight
// above with a 90° field of view, so that u runs over 0.05–0.95 across the image.
Scene textured_floor(const Material& material) {
  Scene scene;
  scene.name = "textured-floor";
  scene.materials = {material};
  TriangleMesh floor;
  floor.positions = {{-100, 0, -100}, {100, 0, -100}, {100, 0, 100}, {-100, 0, 100}};
  floor.indices = {0, 2, 1, 0, 3, 2};
  floor.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  scene.meshes.push_back(floor);
  scene.camera.eye = Vec3f(0, 90, 0);
  scene.camera.target = Vec3f(0, 0, 0);
  scene.camera.up = Vec3f(0, 0, 1);
  scene.camera.fov_degrees = 90.0f;
  return scene;
}

// The image's left blocks see u ≈ 0.72–0.89 (texels 8–15), the right ones u ≈ 0.11–0.28
// (texels 0–7), away from the bilinear blend at u = ½ (see integrator_test.cpp).
Estimate sees_right_texels(const Film& f) { return texture_block(f, 1, 6, 4, 10); }
Estimate sees_left_texels(const Film& f) { return texture_block(f, 12, 6, 15, 10); }

// A directional light of intensity 100 from `radians` off the zenith, in the xy plane.
Light sun_from_zenith(float radians) {
  Light sun;
  sun.type = LightType::directional;
  sun.direction = normalize(Vec3f(std::sin(radians), -std::cos(radians), 0.0f));
  sun.intensity = 100.0f;
  return sun;
}

// Renders a textured material and the constant materials its left and right texels stand
// for, with the same seed and direct light only, in both transports: each half of the
// textured image must equal its constant's (the same random numbers, and the texel is exact
// away from the seam, so only float rounding differs: 1e-4 relative), and the halves must
// differ in `channel` (0–2: X, Y, Z) by over 10 %.
template <class SceneOf>
void expect_halves_match_constants(const SceneOf& scene_of, const Material& textured, const Material& left,
                                   const Material& right, int channel, const char* label) {
  for (const TransportSettings& transport : {rgb_transport(), spectral_transport()}) {
    RenderSettings s = texture_settings_for(transport, 16, 16, 3);
    s.path.max_depth = 1;
    const Film t = render(scene_of(textured), s).film;
    const Estimate t_left = sees_left_texels(t), t_right = sees_right_texels(t);
    const Estimate c_left = sees_left_texels(render(scene_of(left), s).film);
    const Estimate c_right = sees_right_texels(render(scene_of(right), s).film);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(t_left.mean[c], c_left.mean[c], 1e-4 * std::abs(c_left.mean[c]) + 1e-9)
          << label << " " << describe(transport) << " channel " << c;
      EXPECT_NEAR(t_right.mean[c], c_right.mean[c], 1e-4 * std::abs(c_right.mean[c]) + 1e-9)
          << label << " " << describe(transport) << " channel " << c;
    }
    EXPECT_GT(std::abs(t_left.mean[channel] - t_right.mean[channel]), 0.1 * t_right.mean[channel])
        << label << " " << describe(transport);
    std::printf("[ %s ] %s: left half %.4f, right half %.4f (channel %d)\n", label, describe(transport).c_str(),
                t_left.mean[channel], t_right.mean[channel], channel);
  }
}

TEST(MaterialTextures, MetallicRoughnessTextureGivesEachHalfItsConstantsImage) {
  // Left texels: G = 0.3, B = 1 (polished metal); right: G = 1, B = 0 (rough dielectric);
  // the factors (roughness 0.8, metallic 1) multiply them. Lit by a sun at 30° from the
  // zenith, direct light only. Each half must equal a render of the constant material
  // (roughness 0.24, metallic 1) or (0.8, 0) with the same seed: the same random numbers,
  // and the texel is exact away from the seam, so only float rounding differs (1e-4
  // relative). And the halves must differ as the constants do (by over 10 %).
  Material textured;
  textured.type = MaterialType::metallic_roughness;
  textured.base_color = Vec3f(0.9f, 0.6f, 0.3f);
  textured.roughness = 0.8f;
  textured.metallic = 1.0f;
  textured.metallic_roughness_texture = 0;
  const Light sun = sun_from_zenith(0.5236f);
  const auto scene_of = [&](const Material& m) {
    Scene s = textured_floor(m);
    s.lights.push_back(sun);
    s.textures.push_back(two_halves(Vec3f(0.0f, 0.3f, 1.0f), Vec3f(0.0f, 1.0f, 0.0f)));
    return s;
  };
  Material metal = textured, dielectric = textured;
  metal.metallic_roughness_texture = dielectric.metallic_roughness_texture = -1;
  metal.roughness = 0.8f * 0.3f;
  dielectric.metallic = 0.0f;
  expect_halves_match_constants(scene_of, textured, metal, dielectric, 1, "mr-tex");
}

// The textured floor under a sun 70° from the zenith (low, so that sheens and specular
// layers show), with two 16×1 clamped textures of two halves each: texture 0 the colours
// `left` | `right`, texture 1 RGBA texels of alpha `left_alpha` | `right_alpha` (and RGB 0).
Scene floor_with_colour_and_alpha_halves(const Material& m, const Vec3f& left, const Vec3f& right, float left_alpha,
                                         float right_alpha) {
  TextureImage alpha;
  alpha.name = "alpha-halves";
  alpha.width = 16;
  alpha.height = 1;
  alpha.channels = 4;
  for (int i = 0; i < 16; ++i) alpha.texels.insert(alpha.texels.end(), {0.0f, 0.0f, 0.0f, i < 8 ? left_alpha : right_alpha});
  alpha.wrap_u = alpha.wrap_v = TextureWrap::clamp;
  Scene s = textured_floor(m);
  s.lights.push_back(sun_from_zenith(1.2217f));
  s.textures.push_back(two_halves(left, right));
  s.textures.push_back(alpha);
  return s;
}

// KHR_materials_sheen's textures: sheenColorTexture's RGB multiplies the sheen colour, the
// A channel of sheenRoughnessTexture its roughness. Left texels: colour (1, 0.5, 0.2), A =
// 0.5; right: grey 0.2, A = 1; factors white and 0.8. Each half must equal a render of the
// constant sheen, (1, 0.5, 0.2) at r = 0.4 or grey 0.2 at r = 0.8, with the same seed (float
// rounding only, 1e-4 relative), and the halves must differ by over 10 %. A low sun (70°
// from the zenith) shows the sheen; direct light only.
TEST(MaterialTextures, SheenTexturesGiveEachHalfItsConstantsImage) {
  Material textured;
  textured.type = MaterialType::diffuse;
  textured.base_color = Vec3f(0.3f);
  textured.sheen_color = Vec3f(1.0f);
  textured.sheen_roughness = 0.8f;
  textured.sheen_color_texture = 0;
  textured.sheen_roughness_texture = 1;
  const auto scene_of = [&](const Material& m) {
    return floor_with_colour_and_alpha_halves(m, Vec3f(1.0f, 0.5f, 0.2f), Vec3f(0.2f), 0.5f, 1.0f);
  };
  Material left = textured, right = textured;
  left.sheen_color_texture = right.sheen_color_texture = -1;
  left.sheen_roughness_texture = right.sheen_roughness_texture = -1;
  left.sheen_color = Vec3f(1.0f, 0.5f, 0.2f);
  left.sheen_roughness = 0.4f;
  right.sheen_color = Vec3f(0.2f);
  expect_halves_match_constants(scene_of, textured, left, right, 0, "sheen-tex");
}

// KHR_materials_specular's textures: specularColorTexture's RGB multiplies the specular
// colour, the A channel of specularTexture the layer's weight. Left texels: colour
// (1, 0.3, 0.1), A = 0.5; right: grey 0.6, A = 1; factors 0.9 and colour white, on a dark
// metallic_roughness floor of IOR 2 (F0 1/9 × colour). Each half must equal a render of its
// constants, with the same seed (float rounding only, 1e-4 relative), and the halves must
// differ by over 10 %. A sun 70° from the zenith; direct light only.
TEST(MaterialTextures, SpecularTexturesGiveEachHalfItsConstantsImage) {
  Material textured;
  textured.type = MaterialType::metallic_roughness;
  textured.base_color = Vec3f(0.05f);
  textured.metallic = 0.0f;
  textured.roughness = 0.5f;
  textured.ior = 2.0f;
  textured.specular = 0.9f;
  textured.specular_color_texture = 0;
  textured.specular_texture = 1;
  const auto scene_of = [&](const Material& m) {
    return floor_with_colour_and_alpha_halves(m, Vec3f(1.0f, 0.3f, 0.1f), Vec3f(0.6f), 0.5f, 1.0f);
  };
  Material left = textured, right = textured;
  left.specular_color_texture = right.specular_color_texture = -1;
  left.specular_texture = right.specular_texture = -1;
  left.specular_color = Vec3f(1.0f, 0.3f, 0.1f);
  left.specular = 0.45f;
  right.specular_color = Vec3f(0.6f);
  expect_halves_match_constants(scene_of, textured, left, right, 0, "specular-tex");
}

// KHR_materials_iridescence's textures, both read from one image here: the R channel of
// iridescenceTexture multiplies the film's weight, the G channel of
// iridescenceThicknessTexture mixes the thickness range (100–500 nm). Left texels R = 1,
// G = 0.25 (200 nm); right R = 0.5, G = 1 (500 nm); factor 0.9 on a dark metallic_roughness
// floor. Each half must equal a render of its constants (weight 0.9 at 200 nm, 0.45 at 500
// nm) with the same seed (float rounding only, 1e-4 relative), and differ by over 10 %.
TEST(MaterialTextures, IridescenceTexturesGiveEachHalfItsConstantsImage) {
  Material textured;
  textured.type = MaterialType::metallic_roughness;
  textured.base_color = Vec3f(0.05f);
  textured.metallic = 0.0f;
  textured.roughness = 0.4f;
  textured.iridescence = 0.9f;
  textured.iridescence_ior = 1.8f;
  textured.iridescence_thickness_min_nm = 100.0f;
  textured.iridescence_thickness_max_nm = 500.0f;
  textured.iridescence_texture = textured.iridescence_thickness_texture = 0;
  const auto scene_of = [&](const Material& m) {
    return floor_with_colour_and_alpha_halves(m, Vec3f(1.0f, 0.25f, 0.0f), Vec3f(0.5f, 1.0f, 0.0f), 1.0f, 1.0f);
  };
  Material left = textured, right = textured;
  left.iridescence_texture = right.iridescence_texture = -1;
  left.iridescence_thickness_texture = right.iridescence_thickness_texture = -1;
  left.iridescence_thickness_max_nm = 200.0f;
  right.iridescence = 0.45f;
  expect_halves_match_constants(scene_of, textured, left, right, 0, "iridescence-tex");
}

// A quad emitter with an emission texture, facing the camera: glTF's emissive factor c,
// strength s and texel t give radiance c ⊙ t · s in linear Rec.709 (luminance Y(c)·s for a
// white texel, scene-formats.md's mapping of emissive 1 to 1 nit).
Scene emissive_quad(const Vec3f& factor, float strength, const TextureImage& texture) {
  Material m;
  m.base_color = Vec3f(0.0f);  // nothing reflected: the image is the emission alone
  m.emission.color = factor;
  m.emission.luminance_nits = static_cast<float>(relative_luminance(factor, ColorPickerSpace::srgb) * strength);
  m.emission.texture = 0;
  Scene scene = textured_floor(m);
  scene.textures.push_back(texture);
  return scene;
}

TEST(MaterialTextures, EmissiveTextureScalesRadianceByTexelFactorAndStrength) {
  const Vec3f factor(1.0f, 0.8f, 0.5f);
  constexpr float kStrength = 20.0f;
  const Vec3f left_texel(0.2f, 0.6f, 1.0f), right_texel(1.0f, 0.5f, 0.1f);
  const Scene scene = emissive_quad(factor, kStrength, two_halves(left_texel, right_texel));
  // RGB transport (sRGB working space): the film holds c ⊙ t · s exactly; no sampling
  // noise reaches the camera-ray emission, so float accumulation bounds it (1e-4).
  {
    RenderSettings s = texture_settings_for(rgb_transport(), 16, 4, 1);
    s.path.max_depth = 1;
    const Film f = render(scene, s).film;
    const Vec3f left = factor * left_texel * kStrength, right = factor * right_texel * kStrength;
    const Estimate l = sees_left_texels(f), r = sees_right_texels(f);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(l.mean[c], left[c], 1e-4 * left[c] + 1e-6) << "channel " << c;
      EXPECT_NEAR(r.mean[c], right[c], 1e-4 * right[c] + 1e-6) << "channel " << c;
    }
  }
  // Spectral transport: the texel × factor × strength radiance (Rec.709 nits) becomes a
  // spectrum by the transport's rule for RGB radiance (ColorContext::rgb_radiance, as for
  // environment texels). The film's Y must be that spectrum's luminance, integrated here
  // by a 1 nm rule over 360–830 nm, to 5σ of the wavelength-sampling noise plus 1e-3
  // relative for the quadrature. That rule's luminance for saturated colours departs from
  // the RGB colour's Y (sigmoid upsampling is exact only for greys): printed, not asserted.
  {
    RenderSettings s = texture_settings_for(spectral_transport(), 16, 64, 2);
    s.path.max_depth = 1;
    const Film f = render(scene, s).film;
    const ColorContext<SpectralMode<4>> colours(scene, spectral_transport());
    for (const auto& [e, texel] : {std::pair{sees_left_texels(f), left_texel}, std::pair{sees_right_texels(f), right_texel}}) {
      const Vec3f rgb_nits = factor * texel * kStrength;
      double spectral_y = 0.0;
      for (int nm = 360; nm <= 830; ++nm) {
        Wavelengths<SpectralMode<4>> w;
        w.wavelength_nm.fill(static_cast<float>(nm));
        w.pdf.fill(1.0f);
        spectral_y += color::luminance_nits(colours.rgb_radiance(rgb_nits, w), w);
      }
      EXPECT_NEAR(e.mean.y, spectral_y, 5.0 * std::sqrt(e.variance.y) + 1e-3 * spectral_y);
      const double rgb_y = kStrength * relative_luminance(factor * texel, ColorPickerSpace::srgb);
      std::printf("[ emis-tex ] spectral Y %.4f ± %.4f; its spectrum's Y %.4f; RGB Y %.4f (upsampling %+.2f %%)\n",
                  e.mean.y, std::sqrt(e.variance.y), spectral_y, rgb_y, 100.0 * (spectral_y / rgb_y - 1.0));
    }
  }
}

// A grey floor lit only by a 2×2 quad 2 units above it, facing down, whose emission
// texture is a 4×4 pattern with one bright corner quadrant and a dim gradient elsewhere.
// Direct light only; the camera sits between them looking down.
Scene floor_under_textured_emitter() {
  Material floor_material;
  floor_material.base_color = Vec3f(0.5f);
  Material emitter;
  emitter.base_color = Vec3f(0.0f);
  emitter.emission.color = Vec3f(1.0f);
  emitter.emission.luminance_nits = 50.0f;
  emitter.emission.texture = 0;
  Scene scene;
  scene.name = "textured-emitter";
  scene.materials = {floor_material, emitter};
  TriangleMesh floor;
  floor.positions = {{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}};
  floor.indices = {0, 2, 1, 0, 3, 2};
  scene.meshes.push_back(floor);
  TriangleMesh quad;
  quad.positions = {{-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};  // front face down
  quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.material = 1;
  scene.meshes.push_back(quad);
  TextureImage t;
  t.name = "pattern";
  t.width = t.height = 4;
  t.channels = 3;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const bool bright = x < 2 && y < 2;
      const float v = bright ? 1.0f : 0.05f * static_cast<float>(x + y);
      t.texels.insert(t.texels.end(), {v, v * 0.7f, v * 0.4f});
    }
  t.wrap_u = t.wrap_v = TextureWrap::clamp;
  scene.textures.push_back(t);
  scene.camera.eye = Vec3f(0, 1, 0);
  scene.camera.target = Vec3f(0, 0, 0);
  scene.camera.up = Vec3f(0, 0, 1);
  scene.camera.fov_degrees = 90.0f;
  return scene;
}

TEST(MaterialTextures, TexturedEmitterEstimatorsAgree) {
  // NEE (texture at the sampled point, selection by the texture-weighted power), BSDF
  // sampling (texture at the hit) and their MIS combination are three unbiased estimators
  // of the same direct light: whole-image means agree within 5σ of their combined noise,
  // per channel, in RGB and spectral transport. The untextured emitter's image differs
  // (the texture darkens three quadrants), so the test sees the texture at all.
  const Scene scene = floor_under_textured_emitter();
  Scene untextured = scene;
  untextured.materials[1].emission.texture = -1;
  for (const TransportSettings& transport : {rgb_transport(), spectral_transport()}) {
    std::vector<Estimate> estimates;
    for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
      RenderSettings s = texture_settings_for(transport, 16, 256, 17 + static_cast<int>(est));
      s.path.max_depth = 1;
      s.path.estimator = est;
      estimates.push_back(texture_whole_film(render(scene, s).film));
    }
    for (std::size_t a = 0; a < estimates.size(); ++a)
      for (std::size_t b = a + 1; b < estimates.size(); ++b)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(estimates[a].mean[c], estimates[b].mean[c],
                      5.0 * std::sqrt(estimates[a].variance[c] + estimates[b].variance[c]))
              << describe(transport) << " estimators " << a << " and " << b << " channel " << c;
    RenderSettings s = texture_settings_for(transport, 16, 64, 5);
    s.path.max_depth = 1;
    const Estimate plain = texture_whole_film(render(untextured, s).film);
    EXPECT_LT(estimates[0].mean.y, 0.6 * plain.mean.y) << describe(transport);
    std::printf("[ emis-mis ] %s: MIS %.5f ± %.5f, NEE %.5f ± %.5f, BSDF %.5f ± %.5f (untextured %.5f)\n",
                describe(transport).c_str(), estimates[0].mean.y, std::sqrt(estimates[0].variance.y),
                estimates[1].mean.y, std::sqrt(estimates[1].variance.y), estimates[2].mean.y,
                std::sqrt(estimates[2].variance.y), plain.mean.y);
  }
}

}  // namespace
}  // namespace prism
