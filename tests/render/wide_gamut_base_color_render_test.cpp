// Wide-gamut base colours (Material::base_color_space): an ACEScg or Rec.2020 albedo under a
// white light films as itself in RGB transport, and in spectral transport as its own space's
// Jakob–Hanika table upsamples it, which reaches colours outside Rec.709 (render/
// color_context.h). Before base colours had a space, every albedo was read as sRGB: the
// Rec.2020 green below filmed as the sRGB (0.05, 0.6, 0.05), and the sRGB table cannot
// upsample a colour whose Rec.709 red is negative at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"
#include "prism/color/jakob_hanika_table.h"
#include "prism/color/spectrum.h"
#include "prism/io/exr.h"
#include "prism/render/aov_images.h"
#include "prism/render/renderer.h"
#include "prism/scene/emission.h"
#include "prism/scene/texture_file.h"
#include "support/film_statistics.h"
#include "support/scratch_folder.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

constexpr float kSunIlluminanceLux = 50.0f;

struct WideGamutCase {
  Vec3f albedo;
  ColorPickerSpace space;
  bool outside_rec709;
};

// Rec.2020 green and blue and an ACEScg red, all outside Rec.709 (a Rec.709 channel below
// −0.02), and an ACEScg olive inside.
const WideGamutCase kWideGamutCases[] = {{{0.05f, 0.6f, 0.05f}, ColorPickerSpace::rec2020, true},
                       {{0.05f, 0.1f, 0.7f}, ColorPickerSpace::rec2020, true},
                       {{0.45f, 0.03f, 0.02f}, ColorPickerSpace::acescg, true},
                       {{0.2f, 0.5f, 0.1f}, ColorPickerSpace::acescg, false}};

std::string describe(const WideGamutCase& c) {
  return std::string(picker_space_name(c.space)) + " (" + std::to_string(c.albedo.x) + ", " +
         std::to_string(c.albedo.y) + ", " + std::to_string(c.albedo.z) + ")";
}

TEST(WideGamutBaseColour, TheCasesLieWhereTheySay) {
  for (const WideGamutCase& c : kWideGamutCases) {
    const double lowest = min_component(picker_color_in_rec709(c.albedo, c.space));
    if (c.outside_rec709) EXPECT_LT(lowest, -0.02) << describe(c);
    else EXPECT_GT(lowest, 0.0) << describe(c);
  }
}

Scene lit_floor(const Material& material) {
  return test::make_floor_under_overhead_sun(material, kSunIlluminanceLux);  // albedo · E/π everywhere
}

Material diffuse(const WideGamutCase& c) {
  Material m;
  m.type = MaterialType::diffuse;
  m.base_color = c.albedo;
  m.base_color_space = c.space;
  return m;
}

RenderSettings small_render(TransportKind kind, const std::string& working_space = "srgb") {
  RenderSettings s = test::floor_from_above_render_settings(kind);
  s.transport.working_space = working_space;
  return s;
}

Vec3d mean_of(const Scene& scene, const RenderSettings& settings) {
  return test::block_estimate(render(scene, settings).film, 0, 0, 16, 16).mean;
}

TEST(WideGamutBaseColour, FilmsAsItselfInRgbTransport) {
  const double white_nits = kSunIlluminanceLux / std::numbers::pi;
  for (const WideGamutCase& c : kWideGamutCases) {
    const Scene scene = lit_floor(diffuse(c));
    // In its own space: the albedo times the light, up to float accumulation.
    const Vec3d own = mean_of(scene, small_render(TransportKind::rgb, picker_space_name(c.space)));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(own[k], c.albedo[k] * white_nits, 1e-5 * white_nits) << describe(c);
    // In the other wide space: the same colour converted (Bradford between D65 and ACES' white).
    const char* other = c.space == ColorPickerSpace::rec2020 ? "acescg" : "rec2020";
    const Vec3d expected =
        color::conversion_matrix(picker_color_space(c.space), color::color_space(other)) * Vec3d(c.albedo) * white_nits;
    const Vec3d converted = mean_of(scene, small_render(TransportKind::rgb, other));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(converted[k], expected[k], 1e-5 * white_nits) << describe(c) << " in " << other;
    // In sRGB the colours outside Rec.709 are clipped to it: no reflectance is negative.
    const Vec3d srgb = max(picker_color_in_rec709(c.albedo, c.space), Vec3d(0.0)) * white_nits;
    const Vec3d clipped = mean_of(scene, small_render(TransportKind::rgb, "srgb"));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(clipped[k], srgb[k], 1e-5 * white_nits) << describe(c) << " in srgb";
  }
}

TEST(WideGamutBaseColour, FilmsAsItsOwnTableUpsamplesItInSpectralTransport) {
  const double white_nits = kSunIlluminanceLux / std::numbers::pi;
  const color::DenseSpectrum& e = color::standard_illuminant(color::StandardIlluminant::e);
  for (const WideGamutCase& c : kWideGamutCases) {
    const color::ColorSpace& space = picker_color_space(c.space);
    const Mat3 film_to_space = color::spectral_xyz_to_rgb_matrix(space);
    // What the space's table makes of the albedo, filmed under E as the render films it.
    const Vec3d table = film_to_space * color::reflectance_to_xyz(
                                            color::JakobHanikaTable::get(space.name).lookup(Vec3d(c.albedo)), e);
    // The table reproduces these colours to 0.004 per channel (measured: 0.0017 at most, the
    // ACEScg red's red; tests/color/jakob_hanika_test.cpp bounds the tables in ΔE). Colours
    // past the optimal-colour solid are no reflectance and are missed: ACEScg
    // (0.6, 0.02, 0.02) films with red 0.487.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(table[k], c.albedo[k], 0.004) << describe(c);
    const auto estimate = test::block_estimate(render(lit_floor(diffuse(c)), small_render(TransportKind::spectral)).film,
                                               0, 0, 16, 16);
    const Vec3d filmed = film_to_space * estimate.mean;
    // Noise: the film's standard errors carried through the 3×3 matrix by the triangle
    // inequality, at 5σ; the render's wavelength quadrature against the CIE tables'
    // 1 nm sums adds under 1e-4 of the white (UpsampledColourRender's bound is 0.002 with
    // the table's own error in it).
    for (int k = 0; k < 3; ++k) {
      double sigma = 0.0;
      for (int j = 0; j < 3; ++j) sigma += std::abs(film_to_space(k, j)) * std::sqrt(estimate.variance[j]);
      EXPECT_NEAR(filmed[k], table[k] * white_nits, 5.0 * sigma + 1e-3 * white_nits) << describe(c) << " channel " << k;
    }
  }
}

// A texture's texels are Rec.709 and multiply the factor in the material's space: a grey
// texel g gives g × the factor exactly, in both transports, and the albedo AOV says so.
TEST(WideGamutBaseColour, GreyTextureScalesAWideGamutFactor) {
  constexpr float kGrey = 0.5f;
  const WideGamutCase c = kWideGamutCases[0];
  Material untextured = diffuse(c);
  untextured.base_color = c.albedo * kGrey;
  Material textured = diffuse(c);
  Scene a = lit_floor(untextured);
  Scene b = lit_floor(textured);
  TextureImage grey;
  grey.name = "grey";
  grey.width = grey.height = 2;
  grey.channels = 3;
  grey.texels.assign(12, kGrey);
  b.textures.push_back(grey);
  b.materials[0].base_color_texture = 0;
  for (const TransportKind kind : {TransportKind::rgb, TransportKind::spectral}) {
    RenderSettings s = small_render(kind, "rec2020");
    s.aovs = AovSet{true, false, false};  // the albedo
    const RenderResult ra = render(a, s), rb = render(b, s);
    const Vec3d ma = test::block_estimate(ra.film, 0, 0, 16, 16).mean, mb = test::block_estimate(rb.film, 0, 0, 16, 16).mean;
    // The same colour up to the float round-off of Rec.709 → Rec.2020 on the texel (1e-6)
    // and the table's trilinear lookup at it: the same random numbers, so no noise.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mb[k], ma[k], 1e-4 * ma[k] + 1e-6) << static_cast<int>(kind) << " " << k;
    // The albedo AOV, in Rec.2020, is g × the factor for both: single-precision film
    // storage and the conversions there and back (as in aov_test.cpp's 4e-7), 1e-6.
    for (const RenderResult* r : {&ra, &rb}) {
      const Mat3 to_rec2020 = color::conversion_matrix(r->film_space, color::color_space("rec2020"));
      const AovImages aov = film_aov_images(r->film, to_rec2020);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(aov.albedo.rgb[k], c.albedo[k] * kGrey, 1e-6) << static_cast<int>(kind);
    }
  }
}

// An ACEScg OpenEXR texture on an ACEScg material keeps its colour: read into the material's
// space (TextureContent::color_acescg, what the JSON loader asks for), a uniform texture of
// a red outside Rec.709 under a white factor renders as the untextured material of that
// colour, in both transports. Read into Rec.709 instead (the clipped colour every texture
// was before), it renders measurably less saturated.
TEST(WideGamutBaseColour, WideGamutOpenExrTextureKeepsItsColourOnAMaterialInItsSpace) {
  const WideGamutCase c = kWideGamutCases[2];  // the ACEScg red: its Rec.709 green and blue are negative
  ASSERT_EQ(c.space, ColorPickerSpace::acescg);
  test::ScratchFolder dir;
  const color::ColorSpace& aces = color::color_space("acescg");
  const auto f = [](double v) { return static_cast<float>(v); };
  const ExrChromaticities ap1{f(aces.red.x),  f(aces.red.y),  f(aces.green.x), f(aces.green.y),
                              f(aces.blue.x), f(aces.blue.y), f(aces.white.x), f(aces.white.y)};
  std::vector<float> texels;
  for (int t = 0; t < 4; ++t) texels.insert(texels.end(), {c.albedo.x, c.albedo.y, c.albedo.z});
  write_exr(dir / "red.exr", ImageRgbF{2, 2, texels}, ap1);
  const auto textured_scene = [&](TextureContent content) {
    Material m = diffuse(c);
    m.base_color = Vec3f(1.0f);
    Scene scene = lit_floor(m);
    scene.textures.push_back(read_texture_file(dir / "red.exr", TextureEncoding::linear, TextureLimits(64), content));
    scene.materials[0].base_color_texture = 0;
    return scene;
  };
  const Scene kept = textured_scene(TextureContent::color_acescg);
  const Scene clipped = textured_scene(TextureContent::color);
  ASSERT_EQ(kept.textures[0].texel_space, ColorPickerSpace::acescg);
  const Scene untextured = lit_floor(diffuse(c));
  for (const TransportKind kind : {TransportKind::rgb, TransportKind::spectral}) {
    const RenderSettings s = small_render(kind, "acescg");
    const Vec3d expected = mean_of(untextured, s), got = mean_of(kept, s), lost = mean_of(clipped, s);
    std::printf("[ wide texture ] %s: untextured (%.4f, %.4f, %.4f) kept (%.4f, %.4f, %.4f) clipped (%.4f, %.4f, %.4f)\n",
                kind == TransportKind::rgb ? "rgb" : "spectral", expected.x, expected.y, expected.z, got.x, got.y, got.z,
                lost.x, lost.y, lost.z);
    // The texels are the file's floats, read without conversion: the same albedo, the same
    // random numbers, so the same image up to the float product texel × factor (1e-6).
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], expected[k], 1e-5 * expected[k] + 1e-7) << static_cast<int>(kind);
    // Clipped to Rec.709 the red is less saturated: its largest channel change is 75 % (RGB,
    // ACEScg green 0.48 → 0.84) and 16 % (spectral, the film's Z), measured; 10 % is four
    // orders of magnitude beyond the tolerance above.
    double largest_change = 0.0;
    for (int k = 0; k < 3; ++k) largest_change = std::max(largest_change, std::abs(lost[k] - expected[k]) / expected[k]);
    EXPECT_GT(largest_change, 0.1) << static_cast<int>(kind);
  }
}

}  // namespace
}  // namespace prism
