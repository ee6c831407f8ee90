// Environment maps keep their OpenEXR's gamut (TextureContent::color_own_gamut): an ACEScg
// HDRI is held in ACEScg, its texels' radiance is converted (RGB transport) or upsampled
// with ACEScg's table (spectral transport) where it lights the scene, and its importance
// sampling weighs texels by ACEScg's luminance. Converted to Rec.709 at load and clipped
// there, an ACEScg sky would lose its colours outside Rec.709 whatever the working space.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/illuminants.h"
#include "prism/color/jakob_hanika_table.h"
#include "prism/color/spectrum.h"
#include "prism/io/exr.h"
#include "prism/render/renderer.h"
#include "prism/scene/emission.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/scene/texture_file.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

// An ACEScg red outside Rec.709 (its Rec.709 green and blue are negative), as sky radiance
// in nits before the environment's scale.
const Vec3f kSkyAcescg(0.45f, 0.03f, 0.02f);
constexpr double kSkyScale = 2.0;  // the environment's luminance_nits: a scale on the texels
constexpr double kFloorAlbedo = 0.5;

ExrChromaticities chromaticities_of(const char* name) {
  const color::ColorSpace& s = color::color_space(name);
  const auto f = [](double v) { return static_cast<float>(v); };
  return {f(s.red.x), f(s.red.y), f(s.green.x), f(s.green.y), f(s.blue.x), f(s.blue.y), f(s.white.x), f(s.white.y)};
}

// A uniform sky of `rgb` in the primaries of `space`, n × n texels (square: pbrt-v4's
// equal-area maps must be).
void write_sky(const std::filesystem::path& path, const Vec3f& rgb, const char* space, int n = 8) {
  std::vector<float> texels;
  for (int t = 0; t < n * n; ++t) texels.insert(texels.end(), {rgb.x, rgb.y, rgb.z});
  write_exr(path, ImageRgbF{n, n, texels}, chromaticities_of(space));
}

// A grey floor seen from above under the environment map `file` (JSON scene in `dir`).
Scene floor_under_sky(const std::filesystem::path& dir, const std::string& file) {
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [{"name": "grey", "type": "diffuse", "base_color": [0.5, 0.5, 0.5]}],
    "meshes": [{"name": "floor", "material": "grey",
                "positions": [[-100, 0, -100], [100, 0, -100], [100, 0, 100], [-100, 0, 100]],
                "indices": [0, 2, 1, 0, 3, 2]}],
    "camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_degrees": 30},
    "environment": {"texture": ")" + file + R"(", "luminance_nits": 2}})",
                                   "sky.json", dir, "sky");
}

const TextureImage& sky_texture(const Scene& scene) {
  for (const Light& l : scene.lights)
    if (l.type == LightType::environment && l.environment_texture >= 0)
      return scene.textures[static_cast<std::size_t>(l.environment_texture)];
  throw std::runtime_error("the scene has no environment map");
}

// Every loader keeps an ACEScg OpenEXR sky in ACEScg, as written, without a note (nothing
// was converted or clipped); a Rec.709 one stays Rec.709; a Rec.2020 one stays Rec.2020.
TEST(WideGamutEnvironment, LoadersKeepAnOpenExrSkyInItsOwnGamut) {
  test::ScratchFolder dir;
  write_sky(dir / "acescg.exr", kSkyAcescg, "acescg");
  write_sky(dir / "rec2020.exr", kSkyAcescg, "rec2020");
  write_sky(dir / "srgb.exr", kSkyAcescg, "srgb");
  const std::vector<float> as_written = read_texture_file(dir / "srgb.exr", TextureEncoding::linear, TextureLimits(64),
                                                          TextureContent::data)
                                            .linear_values();
  const std::pair<const char*, ColorPickerSpace> files[] = {{"acescg.exr", ColorPickerSpace::acescg},
                                                            {"rec2020.exr", ColorPickerSpace::rec2020},
                                                            {"srgb.exr", ColorPickerSpace::srgb}};
  for (const auto& [file, space] : files) {
    // JSON.
    const Scene json = floor_under_sky(dir.path(), file);
    EXPECT_EQ(sky_texture(json).texel_space, space) << file;
    EXPECT_EQ(sky_texture(json).linear_values(), as_written) << file;
    EXPECT_TRUE(json.warnings.empty()) << file << ": " << (json.warnings.empty() ? "" : json.warnings[0]);
    // pbrt-v4's infinite light.
    const Scene pbrt = loaders::parse_pbrt_scene(std::string("WorldBegin\nLightSource \"infinite\" \"string filename\" \"") +
                                                     file + "\"\nShape \"sphere\"\n",
                                                 "sky.pbrt", dir.path());
    EXPECT_EQ(sky_texture(pbrt).texel_space, space) << file;
    EXPECT_EQ(sky_texture(pbrt).linear_values(), as_written) << file;
    // `prism render --environment FILE`.
    Scene overridden = floor_under_sky(dir.path(), "srgb.exr");
    apply_environment_override(overridden, EnvironmentOverride{(dir / file).string(), 1.0f, 0.0f});
    EXPECT_EQ(sky_texture(overridden).texel_space, space) << file;
    EXPECT_EQ(sky_texture(overridden).linear_values(), as_written) << file;
  }
}

// RGB transport in ACEScg: the floor films ρ · L, the sky's ACEScg radiance itself, on every
// light estimator (a uniform sky: ∫ L cos θ dω = π L over the hemisphere, times ρ/π). Read
// into Rec.709 as every sky was before, the red is clipped and films far less saturated.
TEST(WideGamutEnvironment, AnAcescgSkyLightsAFloorInItsOwnColourInRgbTransport) {
  test::ScratchFolder dir;
  write_sky(dir / "sky.exr", kSkyAcescg, "acescg");
  const Scene kept = floor_under_sky(dir.path(), "sky.exr");
  ASSERT_EQ(sky_texture(kept).texel_space, ColorPickerSpace::acescg);
  Scene clipped = kept;
  clipped.textures[0] = read_texture_file(dir / "sky.exr", TextureEncoding::linear, TextureLimits(64), TextureContent::color);
  ASSERT_EQ(clipped.textures[0].texel_space, ColorPickerSpace::srgb);
  const Vec3d expected = Vec3d(kSkyAcescg) * (kFloorAlbedo * kSkyScale);
  for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
    RenderSettings s = test::direct_light_settings(TransportKind::rgb, est, 64, 5);
    s.transport.working_space = "acescg";
    const test::BlockEstimate e = test::block_estimate(render(kept, s).film, 0, 0, 8, 8);
    // 5σ of the film's noise plus 5e-4 relative (float accumulation), as the other furnaces.
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(e.mean[c], expected[c], 5.0 * std::sqrt(e.variance[c]) + 5e-4 * expected[c])
          << "channel " << c << " estimator " << static_cast<int>(est);
    // Clipped to Rec.709 the film's ACEScg green rises from 0.030 to 0.052 (measured,
    // 1.75 ×): a change of 50 % is far beyond the noise bound above.
    const Vec3d lost = test::block_estimate(render(clipped, s).film, 0, 0, 8, 8).mean;
    std::printf("[ wide sky ] rgb estimator %d: expected (%.4f, %.4f, %.4f) kept (%.4f, %.4f, %.4f) clipped (%.4f, %.4f, %.4f)\n",
                static_cast<int>(est), expected.x, expected.y, expected.z, e.mean.x, e.mean.y, e.mean.z, lost.x, lost.y,
                lost.z);
    EXPECT_GT(std::abs(lost.y - expected.y), 0.5 * expected.y) << static_cast<int>(est);
  }
}

// Spectral transport: the sky's radiance is upsampled with ACEScg's own table (at half its
// largest channel, scaled back: ColorContext::rgb_radiance), so the floor films that
// spectrum, and that spectrum is the ACEScg colour to the table's accuracy. The sRGB table
// cannot hold this red at all (its Rec.709 green and blue are negative).
TEST(WideGamutEnvironment, AnAcescgSkyFilmsAsItsOwnTableUpsamplesItInSpectralTransport) {
  test::ScratchFolder dir;
  write_sky(dir / "sky.exr", kSkyAcescg, "acescg");
  const Scene kept = floor_under_sky(dir.path(), "sky.exr");
  Scene clipped = kept;
  clipped.textures[0] = read_texture_file(dir / "sky.exr", TextureEncoding::linear, TextureLimits(64), TextureContent::color);
  const color::ColorSpace& aces = color::color_space("acescg");
  const Mat3 film_to_aces = color::spectral_xyz_to_rgb_matrix(aces);
  const double m = kSkyAcescg.x;  // the largest channel
  const color::DenseSpectrum& e_light = color::standard_illuminant(color::StandardIlluminant::e);
  // The table's spectrum for the chromaticity (rgb / 2m), filmed under E as the render films
  // it, scaled back by 2m: ACEScg RGB of the sky's upsampled radiance per nit of scale.
  const Vec3d table = film_to_aces * color::reflectance_to_xyz(
                                         color::JakobHanikaTable::get("acescg").lookup(Vec3d(kSkyAcescg) / (2.0 * m)),
                                         e_light) *
                      (2.0 * m);
  // The table reproduces the colour to 0.004 of the half-scaled channel per channel (the
  // bound wide_gamut_base_color_render_test.cpp gives its reflectances), 2m × 0.004 here.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(table[k], kSkyAcescg[k], 2.0 * m * 0.004) << k;
  RenderSettings s = test::direct_light_settings(TransportKind::spectral, LightEstimator::mis, 256, 5);
  const test::BlockEstimate est = test::block_estimate(render(kept, s).film, 0, 0, 8, 8);
  const Vec3d filmed = film_to_aces * est.mean;
  const Vec3d lost = film_to_aces * test::block_estimate(render(clipped, s).film, 0, 0, 8, 8).mean;
  std::printf("[ wide sky ] spectral: table (%.4f, %.4f, %.4f) kept (%.4f, %.4f, %.4f) clipped (%.4f, %.4f, %.4f)\n",
              table.x, table.y, table.z, filmed.x, filmed.y, filmed.z, lost.x, lost.y, lost.z);
  for (int k = 0; k < 3; ++k) {
    const double expected = table[k] * kFloorAlbedo * kSkyScale;
    // Noise: the film's standard errors through the 3×3 matrix by the triangle inequality,
    // at 5σ; plus the render's wavelength quadrature against the CIE tables' 1 nm sums
    // (under 1e-3 of the largest channel, as for the reflectances).
    double sigma = 0.0;
    for (int j = 0; j < 3; ++j) sigma += std::abs(film_to_aces(k, j)) * std::sqrt(est.variance[j]);
    EXPECT_NEAR(filmed[k], expected, 5.0 * sigma + 1e-3 * m * kFloorAlbedo * kSkyScale) << "channel " << k;
  }
  // The clipped sky's green lies far from the kept one's, as in RGB transport (0.052 against
  // 0.029, measured).
  EXPECT_GT(std::abs(lost.y - filmed.y), 0.5 * filmed.y);
}

}  // namespace
}  // namespace prism
