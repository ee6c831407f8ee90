// Spectra given as data, rendered: what the film holds for an emitter's SPD and a measured
// reflectance in spectral and in RGB transport (render/color_context.h, "white-balanced to
// the working white").
#include <gtest/gtest.h>

#include <cmath>

#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/illuminants.h"
#include "prism/render/renderer.h"
#include "prism/scene/spectral_inputs.h"
#include "support/film_statistics.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

constexpr float kLuminanceNits = 100.0f;

// The grey floor of test_scenes.h seen from 5 units above with a 30° field of view (every
// camera ray hits it within 15° of the normal), made of `material`; lights are the caller's.
Scene facing_floor(const Material& material) {
  Scene scene = test::make_grey_floor_seen_from_above(5.0f, 30.0f);
  scene.materials = {material};
  return scene;
}

Material emitter(const color::PiecewiseLinearSpectrum& spd) {
  Material m;
  m.base_color = Vec3f(0.0f);
  m.emission.spectrum = spd;
  m.emission.color = emission_spectrum_srgb(spd);
  m.emission.luminance_nits = kLuminanceNits;
  return m;
}

// Spectral film values are unbiased estimates: the image mean must be within 5σ of the
// expectation (σ from the film's own per-pixel variance; 3 channels, false alarms < 2e-6).
void expect_within_noise(const Film& film, const Vec3d& expected, const char* what) {
  const auto e = test::block_estimate(film, 0, 0, film.width(), film.height());
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.mean[c], expected[c], 5.0 * std::sqrt(e.variance[c]) + 1e-9)
        << what << " channel " << c << ": mean " << e.mean[c] << ", expected " << expected[c];
}

TEST(SpectralInputsRender, EmitterSpdIsBalancedToTheWorkingWhiteInSpectralTransport) {
  // L(λ) = K S(λ)/D65(λ) with 683 ∫ L ȳ = 100 nits: the film (XYZ relative to E) holds
  // 100 · XYZ(S/D65) / Y(S/D65). For D65 itself that is the flat spectrum, (100, 100, 100)
  // up to CIE's ∫x̄ = ∫ȳ = ∫z̄ (1e-4); for F11 it keeps F11's warmth relative to D65.
  const color::DenseSpectrum& d65 = color::standard_illuminant(color::StandardIlluminant::d65);
  for (const char* name : {"D65", "F11", "A"}) {
    const color::PiecewiseLinearSpectrum spd = *named_emission_spectrum(name);
    const Vec3d balanced = color::spectrum_to_xyz([&](double nm) { return spd(nm) / d65(nm); });
    const Film film = render(facing_floor(emitter(spd)), test::floor_from_above_render_settings(TransportKind::spectral)).film;
    expect_within_noise(film, balanced * (kLuminanceNits / balanced.y), name);
  }
  // Without the balance D65 would film as D65's own XYZ, 5 % less x and 9 % more z than
  // white: far outside the bound above (σ is below 0.5 % here).
  const Film d65_film =
      render(facing_floor(emitter(*named_emission_spectrum("D65"))), test::floor_from_above_render_settings(TransportKind::spectral)).film;
  const auto e = test::block_estimate(d65_film, 0, 0, 16, 16);
  EXPECT_NEAR(e.mean.x / e.mean.y, 1.0, 0.01);
  EXPECT_NEAR(e.mean.z / e.mean.y, 1.0, 0.01);
}

TEST(SpectralInputsRender, EmitterSpdIsItsXyzInRgbTransport) {
  // RGB transport: working RGB = sRGB's XYZ → RGB matrix × XYZ(S) scaled to Y = 100 nits,
  // exactly (a constant emitter seen directly has no noise; float film accumulation 1e-5).
  const color::ColorSpace& srgb = color::color_space("srgb");
  for (const char* name : {"F11", "A"}) {
    const color::PiecewiseLinearSpectrum spd = *named_emission_spectrum(name);
    const Vec3d xyz = color::spectrum_to_xyz(spd);
    const Vec3d expected = srgb.xyz_to_rgb * (xyz * (kLuminanceNits / xyz.y));
    const Film film = render(facing_floor(emitter(spd)), test::floor_from_above_render_settings(TransportKind::rgb)).film;
    const Vec3d mean = test::block_estimate(film, 0, 0, 16, 16).mean;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], expected[c], 1e-5 * kLuminanceNits) << name << " channel " << c;
  }
}

TEST(SpectralInputsRender, MeasuredReflectanceUnderWhiteLight) {
  // A white directional light of E lux straight down on the floor: a white Lambertian surface
  // would have L = E/π nits with a flat spectrum (the emission rule for the working white).
  // With reflectance R(λ) the film holds (E/π) · XYZ(R)/∫ȳ in spectral transport, and RGB
  // transport holds exactly that converted to working RGB as a spectral film is (Bradford
  // E → D65, then sRGB): the two transports agree (deterministic: a delta light).
  const color::PiecewiseLinearSpectrum red({400.0, 550.0, 600.0, 700.0}, {0.05, 0.08, 0.6, 0.7});
  Material m;
  m.base_color_spectrum = red;
  m.base_color = reflectance_spectrum_srgb(red);
  Scene scene = facing_floor(m);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = Vec3f(0, -1, 0);
  sun.intensity = 50.0f;
  scene.lights.push_back(sun);
  const double white_nits = 50.0 / std::numbers::pi;

  const Film spectral = render(scene, test::floor_from_above_render_settings(TransportKind::spectral)).film;
  const Vec3d xyz_r = color::spectrum_to_xyz(red);
  const double y_bar_integral = color::spectrum_to_xyz([](double) { return 1.0; }).y;
  expect_within_noise(spectral, xyz_r * (white_nits / y_bar_integral), "spectral");

  const Film rgb = render(scene, test::floor_from_above_render_settings(TransportKind::rgb)).film;
  const Vec3d expected =
      color::spectral_xyz_to_rgb_matrix(color::color_space("srgb")) * xyz_r * (white_nits / y_bar_integral);
  const Vec3d mean = test::block_estimate(rgb, 0, 0, 16, 16).mean;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], std::max(expected[c], 0.0), 1e-5 * white_nits) << "channel " << c;
}

}  // namespace
}  // namespace prism
