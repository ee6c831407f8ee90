// Wide-gamut emitters in spectral transport: a lamp's colour is fitted (the emission rule,
// color/emission_spectrum.h) in its own colour space, adapted from that space's white to E,
// and an emission texture's radiance is upsampled with the table of the emission colour's
// space. Taken through the working space (sRGB by default) first, an ACEScg or Rec.2020
// lamp outside Rec.709 would be clipped to it in a spectral render, though spectral
// transport can carry it whole, and a textured one would be clipped to Rec.709 in any
// working space.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/io/exr.h"
#include "prism/render/renderer.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/json_scene.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

// An ACEScg red outside Rec.709: its Rec.709 green and blue are negative.
const Vec3d kLampAcescg(0.45, 0.03, 0.02);
constexpr double kLampNits = 3.0;

// A camera looking straight up at a large emissive ceiling of `emission` (a JSON object),
// with uvs: every pixel sees the lamp and nothing else. Texture files are found in `dir`.
Scene ceiling(const std::string& emission, const std::filesystem::path& dir = {}) {
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [{"name": "glow", "type": "diffuse", "base_color": [0, 0, 0], "emission": )" + emission + R"(}],
    "meshes": [{"name": "ceiling", "material": "glow",
                "positions": [[-100, 2, -100], [100, 2, -100], [100, 2, 100], [-100, 2, 100]],
                "uvs": [[0, 0], [1, 0], [1, 1], [0, 1]],
                "indices": [0, 1, 2, 0, 2, 3]}],
    "camera": {"eye": [0, 1, 0], "target": [0, 2, 0], "up": [0, 0, 1], "fov_degrees": 30}})",
                                   "ceiling.json", dir, "ceiling");
}

std::string acescg_lamp(double nits) {
  return R"({"color": [0.45, 0.03, 0.02], "color_space": "acescg", "luminance_nits": )" + std::to_string(nits) + "}";
}

// A spectral film holds CIE XYZ relative to E, Y in nits: the film's mean over the image and
// the standard error of that mean, per channel.
test::BlockEstimate film_xyz(const Scene& scene, const std::string& working_space) {
  RenderSettings s = test::direct_light_settings(TransportKind::spectral, LightEstimator::mis, 256, 7);
  s.transport.working_space = working_space;
  return test::block_estimate(render(scene, s).film, 0, 0, 8, 8);
}

// An ACEScg colour's XYZ adapted from ACES' white to E (Bradford), as the emission rule
// and the E-relative tables see it.
Vec3d acescg_xyz_under_e(const Vec3d& rgb) {
  const color::ColorSpace& aces = color::color_space("acescg");
  return color::working_to_e_adaptation(aces) * (aces.rgb_to_xyz * rgb);
}

TEST(WideGamutEmission, AnAcescgLampFilmsAsItsColourInSpectralTransportWhateverTheWorkingSpace) {
  const Scene scene = ceiling(acescg_lamp(kLampNits));
  // The emission rule: the colour adapted to E, its spectrum scaled so that the luminance
  // the film shows in the lamp's own space (the E-relative XYZ adapted back to the ACES
  // white) is the lamp's: that is the colour's own Y there, which Bradford does not keep
  // for a saturated red (the E-relative Y is about 4 % higher).
  const Vec3d adapted = acescg_xyz_under_e(kLampAcescg);
  const Vec3d expected = adapted * (kLampNits / (color::color_space("acescg").rgb_to_xyz * kLampAcescg).y);
  // Clipped to Rec.709 as the sRGB working space did before (the same rule on the clip).
  const Mat3 to_rec709 = color::conversion_matrix(color::color_space("acescg"), color::color_space("srgb"));
  const Vec3d clip = color::working_to_e_adaptation(color::color_space("srgb")) *
                     (color::color_space("srgb").rgb_to_xyz * max(to_rec709 * kLampAcescg, Vec3d(0.0)));
  const Vec3d clipped = clip * (kLampNits / clip.y);
  for (const char* working : {"srgb", "rec2020", "acescg"}) {
    const test::BlockEstimate e = film_xyz(scene, working);
    std::printf("[ wide lamp ] working %s: XYZ expected (%.4f, %.4f, %.4f) filmed (%.4f, %.4f, %.4f) ± (%.4f, %.4f, "
                "%.4f), clipped would be (%.4f, %.4f, %.4f)\n",
                working, expected.x, expected.y, expected.z, e.mean.x, e.mean.y, e.mean.z, std::sqrt(e.variance.x),
                std::sqrt(e.variance.y), std::sqrt(e.variance.z), clipped.x, clipped.y, clipped.z);
    // 5σ of the wavelengths' noise, plus the fit (Gauss–Newton to the adapted XYZ) and the
    // render's wavelength quadrature against the CIE tables' 1 nm sums: 1e-3 of the
    // luminance (the bound the base colours' renders use).
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(e.mean[k], expected[k], 5.0 * std::sqrt(e.variance[k]) + 1e-3 * kLampNits)
          << working << " channel " << k;
  }
}

// A grey texture g on a wide-gamut lamp: its texels multiply the colour in the colour's own
// space (colour × luminance / its Y there, scene/emission.h), and that radiance is
// upsampled with the space's table (ColorContext::rgb_radiance), which films it as the
// colour adapted to E, to the table's accuracy.
TEST(WideGamutEmission, AWideGamutLampsTextureKeepsItsColourInSpectralTransport) {
  constexpr double kGrey = 0.5;
  Scene textured = ceiling(acescg_lamp(kLampNits));
  TextureImage grey;
  grey.name = "grey";
  grey.width = grey.height = 2;
  grey.channels = 3;
  grey.texels.assign(12, static_cast<float>(kGrey));
  textured.textures.push_back(grey);
  textured.materials[0].emission.texture = 0;
  const double scale = kGrey * kLampNits / relative_luminance(Vec3f(kLampAcescg), ColorPickerSpace::acescg);
  const Vec3d radiance = kLampAcescg * scale;  // ACEScg, nits
  const Vec3d expected = acescg_xyz_under_e(radiance);
  const test::BlockEstimate e = film_xyz(textured, "srgb");
  std::printf("[ wide lamp ] textured: XYZ expected (%.4f, %.4f, %.4f) filmed (%.4f, %.4f, %.4f) ± (%.4f, %.4f, %.4f)\n",
              expected.x, expected.y, expected.z, e.mean.x, e.mean.y, e.mean.z, std::sqrt(e.variance.x),
              std::sqrt(e.variance.y), std::sqrt(e.variance.z));
  // The ACEScg table reproduces a colour to 0.004 per channel of the half-scaled colour
  // (the bound wide_gamut_base_color_render_test.cpp gives it): 0.004 × 2m in ACEScg,
  // carried into XYZ by the absolute row sums of the matrix; plus 5σ of the noise.
  const color::ColorSpace& aces = color::color_space("acescg");
  const Mat3 a = color::working_to_e_adaptation(aces) * aces.rgb_to_xyz;
  for (int k = 0; k < 3; ++k) {
    const double table = (std::abs(a(k, 0)) + std::abs(a(k, 1)) + std::abs(a(k, 2))) * 0.004 * 2.0 * radiance.x;
    EXPECT_NEAR(e.mean[k], expected[k], 5.0 * std::sqrt(e.variance[k]) + table) << "channel " << k;
  }
}

// A Rec.709 texture (a PNG's, or one made in code) on an ACEScg lamp is converted to ACEScg
// and multiplies the colour there, as a base colour texture's texels do: in RGB transport
// in ACEScg the ceiling films conversion(texel) × L / Y(colour). The Rec.709 numbers
// multiplying the ACEScg colour unconverted would film a more saturated red.
TEST(WideGamutEmission, ARec709TextureOnAWideGamutLampIsConvertedToTheLampsSpace) {
  const Vec3f texel(0.8f, 0.2f, 0.1f);
  Scene scene = ceiling(R"({"color": [1, 1, 1], "color_space": "acescg", "luminance_nits": 3})");
  TextureImage t;
  t.name = "rec709";
  t.width = t.height = 2;
  t.channels = 3;
  for (int i = 0; i < 4; ++i) t.texels.insert(t.texels.end(), {texel.x, texel.y, texel.z});
  scene.textures.push_back(t);
  scene.materials[0].emission.texture = 0;
  RenderSettings s = test::direct_light_settings(TransportKind::rgb, LightEstimator::mis, 4, 7);
  s.transport.working_space = "acescg";
  const Vec3d got = test::block_estimate(render(scene, s).film, 0, 0, 8, 8).mean;
  // The white's Y is 1 in ACEScg: L / Y(colour) = 3.
  const Vec3d expected =
      color::conversion_matrix(color::color_space("srgb"), color::color_space("acescg")) * Vec3d(texel) * 3.0;
  std::printf("[ wide lamp ] Rec.709 texture: expected (%.4f, %.4f, %.4f) filmed (%.4f, %.4f, %.4f)\n", expected.x,
              expected.y, expected.z, got.x, got.y, got.z);
  // The lamp is seen directly and nothing else is lit (its base colour is black): no noise,
  // float accumulation only (1e-5).
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], expected[k], 1e-5 * expected[k]) << "channel " << k;
}

// JSON: an OpenEXR emission texture is read into the lamp's colour space, so an ACEScg file
// on an `acescg` lamp is kept as written (no conversion, no clip, no warning), and a
// Rec.709 lamp's is converted to Rec.709 as before.
TEST(WideGamutEmission, JsonReadsAnOpenExrEmissionTextureIntoTheLampsSpace) {
  test::ScratchFolder dir;
  const color::ColorSpace& aces = color::color_space("acescg");
  const auto f = [](double v) { return static_cast<float>(v); };
  const ExrChromaticities ap1{f(aces.red.x),  f(aces.red.y),  f(aces.green.x), f(aces.green.y),
                              f(aces.blue.x), f(aces.blue.y), f(aces.white.x), f(aces.white.y)};
  const std::vector<float> texels = {0.45f, 0.03f, 0.02f, 0.45f, 0.03f, 0.02f};
  write_exr(dir / "glow.exr", ImageRgbF{2, 1, texels}, ap1);
  const Scene kept = ceiling(R"({"color": [1, 1, 1], "color_space": "acescg", "luminance_nits": 3, "texture": "glow.exr"})",
                             dir.path());
  const TextureImage& k = kept.textures[static_cast<std::size_t>(kept.materials[0].emission.texture)];
  EXPECT_EQ(k.texel_space, ColorPickerSpace::acescg);
  EXPECT_EQ(k.linear_values(), texels);
  EXPECT_TRUE(kept.warnings.empty());
  const Scene rec709 = ceiling(R"({"color": [1, 1, 1], "luminance_nits": 3, "texture": "glow.exr"})", dir.path());
  const TextureImage& r = rec709.textures[static_cast<std::size_t>(rec709.materials[0].emission.texture)];
  EXPECT_EQ(r.texel_space, ColorPickerSpace::srgb);
  EXPECT_FALSE(rec709.warnings.empty());  // converted from ACEScg and clipped: said
}

}  // namespace
}  // namespace prism
