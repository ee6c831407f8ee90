// A constant (untextured) environment is an emitter like the others: its colour or its
// spectrum and its luminance go through the emission rule (render/color_context.h). A light
// sampler that gave a constant sky the grey of its luminance would render a JSON `"color"`
// or a pbrt-v4 `"rgb L"` sky grey; these tests pin the colour on every path that meets the
// sky: NEE, BSDF sampling, MIS and camera rays.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/color/color_space.h"
#include "prism/color/illuminants.h"
#include "prism/color/spectrum.h"
#include "prism/core/error.h"
#include "prism/render/renderer.h"
#include "prism/scene/emission.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "scene/loaders/loader_test_files.h"
#include "support/direct_light_settings.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using Estimate = test::BlockEstimate;

// A grey floor (ρ = 0.5) seen from above, or (looking_up) nothing but the sky, under the
// given environment object.
Scene sky_scene(const std::string& environment, bool looking_up = false) {
  const std::string target = looking_up ? "[0, 2, 0]" : "[0, 0, 0]";
  const std::string camera = R"({"eye": [0, 1, 0], "target": )" + target + R"(, "up": [0, 0, 1], "fov_degrees": 30})";
  return loaders::parse_json_scene(R"({"format": "prism-scene/1",
    "materials": [{"name": "grey", "type": "diffuse", "base_color": [0.5, 0.5, 0.5]}],
    "meshes": [{"name": "floor", "material": "grey",
                "positions": [[-100, 0, -100], [100, 0, -100], [100, 0, 100], [-100, 0, 100]],
                "indices": [0, 2, 1, 0, 3, 2]}],
    "camera": )" + camera + R"(,
    "environment": )" + environment + "}",
                                   "sky.json", {}, "sky");
}

RenderSettings settings(TransportKind kind, LightEstimator estimator, int spp) {
  return test::direct_light_settings(kind, estimator, spp, 5);
}

Estimate whole(const Film& film) { return test::block_estimate(film, 0, 0, film.width(), film.height()); }

// Working RGB (sRGB) of an SPD at luminance `nits`: what RGB transport makes of a spectral
// emitter (its CIE XYZ, unadapted).
Vec3d srgb_of_spectrum(const color::DenseSpectrum& spd, double nits) {
  const Vec3d xyz = color::spectrum_to_xyz(spd);
  return color::color_space("srgb").xyz_to_rgb * (xyz * (nits / xyz.y));
}

TEST(ConstantEnvironment, ItsColourLightsAFloorOnEveryEstimator) {
  // ∫ L cos θ dω over the floor's hemisphere = π L; times ρ/π: ρ L per channel, where L is
  // the colour scaled to the sky's luminance (the emission rule). 5σ of the film's noise
  // plus 5e-4 relative (float accumulation), as the other furnaces.
  const Vec3f colour(0.8f, 0.5f, 0.2f);
  const double nits = 4.0;
  const Scene scene = sky_scene(R"({"color": [0.8, 0.5, 0.2], "luminance_nits": 4})");
  const Vec3d expected = Vec3d(colour.x, colour.y, colour.z) *
                         (0.5 * nits / relative_luminance(colour, ColorPickerSpace::srgb));
  for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
    const Estimate e = whole(render(scene, settings(TransportKind::rgb, est, 64)).film);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(e.mean[c], expected[c], 5.0 * std::sqrt(e.variance[c]) + 5e-4 * expected[c])
          << "channel " << c << " estimator " << static_cast<int>(est);
  }
}

TEST(ConstantEnvironment, ItsSpectrumIsTheSpectrumsColourInRgbTransport) {
  // Camera rays see the sky alone: every sample is the sky's radiance, no noise.
  const Scene scene = sky_scene(R"({"spectrum": "A", "luminance_nits": 3})", /*looking_up=*/true);
  ASSERT_TRUE(scene.lights[0].spectrum.has_value());
  const Vec3d expected = srgb_of_spectrum(color::standard_illuminant(color::StandardIlluminant::a), 3.0);
  ASSERT_GT(expected.x, 1.5 * expected.z);  // tungsten's orange, not grey
  const Estimate e = whole(render(scene, settings(TransportKind::rgb, LightEstimator::mis, 4)).film);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], expected[c], 1e-3 * expected[c]) << "channel " << c;
}

// In spectral transport the sky must be the emitter its colour or spectrum describes: the
// same film as a surface emitter of that colour (or spectrum) and luminance filling the view.
TEST(ConstantEnvironment, SpectralSkyMatchesASurfaceEmitterOfTheSameColour) {
  for (const std::string colour : {R"("color": [0.8, 0.5, 0.2])", R"("spectrum": "A")", R"("spectrum": "F11")"}) {
    const Scene sky = sky_scene("{" + colour + R"(, "luminance_nits": 3})", /*looking_up=*/true);
    const Scene surface = loaders::parse_json_scene(R"({"format": "prism-scene/1",
      "materials": [{"name": "glow", "type": "diffuse", "base_color": [0, 0, 0],
                     "emission": {)" + colour + R"(, "luminance_nits": 3}}],
      "meshes": [{"name": "ceiling", "material": "glow",
                  "positions": [[-100, 2, -100], [100, 2, -100], [100, 2, 100], [-100, 2, 100]],
                  "indices": [0, 1, 2, 0, 2, 3]}],
      "camera": {"eye": [0, 1, 0], "target": [0, 2, 0], "up": [0, 0, 1], "fov_degrees": 30}})",
                                                    "surface.json", {}, "surface");
    const Estimate a = whole(render(sky, settings(TransportKind::spectral, LightEstimator::mis, 64)).film);
    const Estimate b = whole(render(surface, settings(TransportKind::spectral, LightEstimator::mis, 64)).film);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(a.mean[c], b.mean[c], 5.0 * std::sqrt(a.variance[c] + b.variance[c]) + 1e-4 * b.mean[c])
          << colour << " component " << c;
    EXPECT_NEAR(a.mean.y, 3.0, 0.05 * 3.0) << colour;  // the film's Y is the luminance
  }
}

TEST(ConstantEnvironment, PbrtRgbAndSpectrumSkiesKeepTheirColour) {
  const auto sky = [](const std::string& light) {
    return loaders::parse_pbrt_scene(R"(LookAt 0 0 0  0 0 1  0 1 0
Camera "perspective" "float fov" 30
WorldBegin
LightSource "infinite" )" + light + R"(
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Translate 0 0 -5
Shape "sphere" "float radius" 0.01
)",
                                     "sky.pbrt", {});
  };
  // "rgb L": the colour, with luminance scale · Y(L) (pbrt-v4's RGB illuminant, luminance kept).
  const Scene rgb = sky(R"("rgb L" [0.2 0.5 0.9] "float scale" 2)");
  const Estimate e = whole(render(rgb, settings(TransportKind::rgb, LightEstimator::mis, 4)).film);
  const Vec3d expected = Vec3d(0.2, 0.5, 0.9) * 2.0;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], expected[c], 1e-3 * expected[c]) << "channel " << c;
  // "spectrum L": the spectrum, normalised to luminance `scale` as pbrt-v4 normalises light spectra.
  const Scene a = sky(R"("spectrum L" "stdillum-A" "float scale" 2)");
  ASSERT_TRUE(a.lights[0].spectrum.has_value());
  const Vec3d expected_a = srgb_of_spectrum(color::standard_illuminant(color::StandardIlluminant::a), 2.0);
  const Estimate ea = whole(render(a, settings(TransportKind::rgb, LightEstimator::mis, 4)).film);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ea.mean[c], expected_a[c], 1e-3 * expected_a[c]) << "channel " << c;
}

TEST(ConstantEnvironment, AMapTakesNoColourOrSpectrum) {
  for (const char* key : {R"("color": [1, 0, 0])", R"("spectrum": "D65")", R"("color_space": "acescg")"}) {
    const std::string message = test::error_of<SceneError>(
        [&] { sky_scene(std::string(R"({"luminance_nits": 1, "texture": "sky.hdr", )") + key + "}"); });
    EXPECT_NE(message.find("takes no colour"), std::string::npos) << message;
  }
  const std::string both = test::error_of<SceneError>(
      [] { sky_scene(R"({"luminance_nits": 1, "color": [1, 1, 1], "spectrum": "D65"})"); });
  EXPECT_NE(both.find("either 'color' or 'spectrum'"), std::string::npos) << both;
}

}  // namespace
}  // namespace prism
