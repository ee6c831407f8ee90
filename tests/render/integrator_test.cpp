// The wavefront integrator against closed-form answers, in every transport mode:
// uniform emitting enclosures (with objects that must be invisible in them), direct light
// from point, spot and directional lights, estimator agreement for a sun disc, lamps of two
// colours adding up, and the colour of the first stratified spectral sample.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/loaders/sphere_mesh.h"
#include "support/film_statistics.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

using Estimate = test::BlockEstimate;

Estimate block(const Film& film, int x0, int y0, int x1, int y1) { return test::block_estimate(film, x0, y0, x1, y1); }

Estimate whole_film(const Film& film) { return block(film, 0, 0, film.width(), film.height()); }

struct ModeCase {
  const char* name;
  TransportSettings transport;
};

std::vector<ModeCase> all_modes() {
  std::vector<ModeCase> modes;
  TransportSettings rgb;
  rgb.kind = TransportKind::rgb;
  modes.push_back({"rgb-srgb", rgb});
  rgb.working_space = "acescg";
  modes.push_back({"rgb-acescg", rgb});
  for (int n : {3, 4, 8})
    for (auto strategy : {color::WavelengthStrategy::hero, color::WavelengthStrategy::cosh, color::WavelengthStrategy::cosh3}) {
      TransportSettings t;
      t.wavelengths = n;
      t.wavelength_strategy = strategy;
      modes.push_back({"spectral", t});
    }
  return modes;
}

RenderSettings settings_for(const TransportSettings& transport, int size, int spp, std::uint64_t seed = 1) {
  RenderSettings s;
  s.width = s.height = size;
  s.samples_per_pixel = spp;
  s.seed = seed;
  s.transport = transport;
  return s;
}

// With an equal-energy white emitter and grey albedo, every mode's film holds the same
// numbers in every channel: RGB films because white is (1,1,1)·Y, spectral films because
// XYZ of an E-white is X = Y = Z. 5σ bounds: false alarms below 6e-7 per comparison.
void expect_uniform(const Film& film, double expected, const std::string& what) {
  const Estimate e = whole_film(film);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.mean[c], expected, 5.0 * std::sqrt(e.variance[c]) + 1e-5 * expected) << what << " channel " << c;
}

TEST(Integrator, EmittingEnclosureInEveryTransportMode) {
  constexpr float kAlbedo = 0.5f, kEmitted = 1.0f;
  const Scene scene = test::make_emitting_enclosure(kAlbedo, kEmitted);
  for (const ModeCase& m : all_modes()) {
    RenderSettings s = settings_for(m.transport, 16, 32);
    s.path.max_depth = 200;
    expect_uniform(render(scene, s).film, kEmitted / (1.0 - kAlbedo), describe(m.transport));
  }
}

// Non-absorbing objects in a uniform radiance field are invisible: a smooth glass
// polyhedron (constant and dispersive IOR — the latter exercises hero-wavelength
// termination) and a perfect mirror leave L = Le/(1 − a) everywhere. Flat shading:
// interpolated normals would break energy conservation by design.
TEST(Integrator, LosslessObjectsVanishInAUniformField) {
  constexpr float kAlbedo = 0.5f, kEmitted = 1.0f;
  for (const char* kind : {"glass", "dispersive-glass", "mirror"}) {
    Scene scene = test::make_emitting_enclosure(kAlbedo, kEmitted);
    Material object;
    object.name = kind;
    if (std::string(kind) == "mirror") {
      object.type = MaterialType::mirror;
      object.base_color = Vec3f(1.0f);
    } else {
      object.type = MaterialType::dielectric;
      object.base_color = Vec3f(1.0f);  // clear: the base colour tints transmission
      object.roughness = 0.0f;
      object.ior = 1.5f;
      if (std::string(kind) == "dispersive-glass") {
        object.dispersion = DispersionModel::cauchy;
        object.dispersion_coefficients = {1.5f, 0.02f, 0, 0, 0, 0};  // strong dispersion
      }
    }
    scene.materials.push_back(object);
    TriangleMesh sphere = loaders::make_uv_sphere(Vec3f(0.3f, 0.2f, 0.6f), 0.35f, 12);
    sphere.normals.clear();
    sphere.material = 1;
    scene.meshes.push_back(sphere);
    for (const ModeCase& m : {all_modes()[0], all_modes()[5], all_modes().back()}) {
      RenderSettings s = settings_for(m.transport, 16, 64);
      s.path.max_depth = 200;
      expect_uniform(render(scene, s).film, kEmitted / (1.0 - kAlbedo), std::string(kind) + " " + describe(m.transport));
    }
  }
}

// The same with geometry too big for the caches (over 512 KiB of indices and vertices), so
// that shading prefetches each hit's vertices a few slots ahead (surface_interaction.h):
// a mirror sphere of ≈ 29 000 triangles must still vanish, and the prefetches' loads of
// index triples stay in bounds (checked under AddressSanitizer in CI).
TEST(Integrator, LosslessGeometryBeyondTheCachesVanishesToo) {
  constexpr float kAlbedo = 0.5f, kEmitted = 1.0f;
  Scene scene = test::make_emitting_enclosure(kAlbedo, kEmitted);
  Material mirror;
  mirror.name = "mirror";
  mirror.type = MaterialType::mirror;
  mirror.base_color = Vec3f(1.0f);
  scene.materials.push_back(mirror);
  TriangleMesh sphere = loaders::make_uv_sphere(Vec3f(0.3f, 0.2f, 0.6f), 0.35f, 120);
  sphere.normals.clear();
  sphere.material = static_cast<std::uint32_t>(scene.materials.size() - 1);
  const std::size_t bytes = sphere.indices.size() * sizeof(std::uint32_t) + sphere.positions.size() * sizeof(Vec3f) +
                            sphere.uvs.size() * sizeof(Vec2f) + sphere.tangents.size() * sizeof(Vec3f);
  ASSERT_GT(bytes, std::size_t{512} << 10);  // wavefront_integrator.cpp's threshold for prefetching
  scene.meshes.push_back(std::move(sphere));
  for (const ModeCase& m : {all_modes()[0], all_modes().back()}) {
    RenderSettings s = settings_for(m.transport, 16, 32);
    s.path.max_depth = 200;
    expect_uniform(render(scene, s).film, kEmitted / (1.0 - kAlbedo), "large mirror " + describe(m.transport));
  }
}

// A grey floor (ρ = 0.5, flat spectrum) seen from straight above through a narrow field
// of view, lit by one delta light, direct light only: L = ρ/π · E_perp with E_perp the
// illuminance on the floor. RGB transport has no sampling noise here (bound: float
// accumulation, 1e-4 relative); spectral transport keeps the noise of estimating Y from
// sampled wavelengths (ȳ/p varies with λ), so its bound adds 5σ.
Scene lit_floor(const Light& light) {
  Scene scene = test::make_grey_floor_seen_from_above(10.0f, 0.01f);
  scene.name = "lit-floor";
  scene.lights.push_back(light);
  return scene;
}

void expect_floor_radiance(const Light& light, double illuminance_lux, const char* what) {
  const Scene scene = lit_floor(light);
  for (const ModeCase& m : {all_modes()[0], all_modes()[1], all_modes()[5]}) {
    RenderSettings s = settings_for(m.transport, 8, 64);
    s.path.max_depth = 1;
    const double expected = 0.5 / std::numbers::pi * illuminance_lux;
    const Estimate e = whole_film(render(scene, s).film);
    EXPECT_NEAR(e.mean.y, expected, 5.0 * std::sqrt(e.variance.y) + 1e-4 * expected) << what << " " << describe(m.transport);
  }
}

TEST(Integrator, DirectionalLightGivesLambertianRadiance) {
  Light sun;
  sun.type = LightType::directional;
  sun.direction = normalize(Vec3f(std::sin(1.0f), -std::cos(1.0f), 0.0f));  // 1 rad from zenith
  sun.intensity = 1000.0f;  // lux on a surface facing the light
  expect_floor_radiance(sun, 1000.0 * std::cos(1.0), "directional");
}

TEST(Integrator, PointAndSpotLightsFollowTheInverseSquareLaw) {
  Light point;
  point.type = LightType::point;
  point.position = Vec3f(3, 4, 0);  // 5 units away, 4 above: E = I cos θ / r² = I · 4/125
  point.intensity = 100.0f;
  expect_floor_radiance(point, 100.0 * 4.0 / 125.0, "point");
  Light spot = point;
  spot.type = LightType::spot;
  spot.direction = normalize(Vec3f(-3, -4, 0));  // aimed at the viewed spot: inside the inner cone
  expect_floor_radiance(spot, 100.0 * 4.0 / 125.0, "spot");
  spot.direction = Vec3f(0, -1, 0);  // 36.9° off axis: outside a 20°/30° cone, no light
  spot.spot_inner_angle_degrees = 20.0f;
  spot.spot_outer_angle_degrees = 30.0f;
  const Estimate dark = whole_film(render(lit_floor(spot), settings_for(all_modes()[0].transport, 4, 4)).film);
  EXPECT_EQ(dark.mean.y, 0.0);
}

TEST(Integrator, SunDiscEstimatorsAgree) {
  // A sun with a 20° disc over a grey floor: NEE, BSDF sampling and MIS are three
  // unbiased estimators of the same direct light; 5σ bounds.
  Light sun;
  sun.type = LightType::directional;
  sun.direction = normalize(Vec3f(0.4f, -1.0f, 0.1f));
  sun.intensity = 1000.0f;
  sun.angular_diameter_degrees = 20.0f;
  Scene scene = lit_floor(sun);
  scene.camera.fov_degrees = 30.0f;
  std::vector<Estimate> estimates;
  for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
    RenderSettings s = settings_for(all_modes()[5].transport, 16, 128, 7 + static_cast<int>(est));
    s.path.max_depth = 1;
    s.path.estimator = est;
    estimates.push_back(whole_film(render(scene, s).film));
  }
  for (std::size_t a = 0; a < estimates.size(); ++a)
    for (std::size_t b = a + 1; b < estimates.size(); ++b)
      EXPECT_NEAR(estimates[a].mean.y, estimates[b].mean.y,
                  5.0 * std::sqrt(estimates[a].variance.y + estimates[b].variance.y))
          << "estimators " << a << " and " << b;
}

TEST(Integrator, LampsOfTwoColoursAddUpInSpectralTransport) {
  // The Cornell box, its walls white, lit by two point lamps instead of its own: one emits
  // only at 600–700 nm, the other only at 420–480 nm. Every vertex of a path samples one
  // lamp or the other, so one path's light samples switch between two spectra that share
  // no wavelength (the integrator keeps the last lamp's spectrum per path,
  // WavefrontIntegrator::untextured_emission: a stale one would move light from one band
  // to the other). Light adds linearly, so the box lit by both must be the box lit by each
  // alone, summed: 5σ per channel, the three renders' variances added (false alarms below
  // 6e-7 per comparison).
  const auto band = [](double from_nm, double to_nm) {
    return color::PiecewiseLinearSpectrum({380.0, from_nm - 1.0, from_nm, to_nm, to_nm + 1.0, 780.0},
                                          {0.0, 0.0, 1.0, 1.0, 0.0, 0.0});
  };
  const auto box_lit_by = [&](bool red, bool blue) {
    Scene scene = make_cornell_box();
    for (Material& m : scene.materials) {
      m.emission.luminance_nits = 0.0f;  // its own lamp off
      m.base_color = Vec3f(0.9f);        // most light reaches the film after several vertices
    }
    Light lamp;
    lamp.type = LightType::point;
    lamp.intensity = 2.0e5f;  // cd, in a box 555 units wide
    if (red) {
      lamp.position = Vec3f(40, 80, 300);
      lamp.color = Vec3f(1.0f, 0.05f, 0.0f);  // the band's Rec.709 approximation, as the loaders store one
      lamp.spectrum = band(600.0, 700.0);
      scene.lights.push_back(lamp);
    }
    if (blue) {
      lamp.position = Vec3f(515, 80, 300);
      lamp.color = Vec3f(0.05f, 0.1f, 1.0f);
      lamp.spectrum = band(420.0, 480.0);
      scene.lights.push_back(lamp);
    }
    RenderSettings s = settings_for(TransportSettings{}, 16, 128, red && blue ? 11 : red ? 12 : 13);
    const Film film = render(scene, s).film;
    return std::array<Estimate, 2>{block(film, 0, 0, 8, 16), block(film, 8, 0, 16, 16)};
  };
  // Half the image at a time: a stale spectrum's error has opposite signs on the two lamps'
  // sides (and nearly cancels over the whole box, where light is chosen by power).
  const auto both = box_lit_by(true, true), red = box_lit_by(true, false), blue = box_lit_by(false, true);
  for (int half = 0; half < 2; ++half)
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(red[half].mean[c] + blue[half].mean[c], 0.0) << "half " << half << " channel " << c;
      EXPECT_NEAR(both[half].mean[c], red[half].mean[c] + blue[half].mean[c],
                  5.0 * std::sqrt(both[half].variance[c] + red[half].variance[c] + blue[half].variance[c]))
          << "half " << half << " channel " << c;
    }
}

// CIE xy of a film block (spectral films hold XYZ).
std::pair<double, double> chromaticity(const Estimate& e) {
  const double sum = e.mean.x + e.mean.y + e.mean.z;
  return {e.mean.x / sum, e.mean.y / sum};
}

TEST(Integrator, StratifiedWavelengthsAreUnbiasedOverWholeGroups) {
  // The seed renderer's nine wavelength strata: over a whole group of nine samples per
  // pixel every stratum is used once, so the mean colour of the Cornell box's white back
  // wall must match an unstratified converged render within noise (5σ per channel).
  const Scene scene = make_cornell_box();
  TransportSettings plain;
  TransportSettings stratified;
  stratified.stratify_first_wavelengths = true;
  const auto wall = [](const Film& f) { return block(f, 10, 8, 22, 14); };
  const Estimate reference = wall(render(scene, settings_for(plain, 32, 90, 3)).film);
  const Estimate grouped = wall(render(scene, settings_for(stratified, 32, 18, 4)).film);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(grouped.mean[c], reference.mean[c], 5.0 * std::sqrt(grouped.variance[c] + reference.variance[c]))
        << "channel " << c;
  // The first sample is coloured, not grey noise: its chromaticity is reported (see the
  // issue note: it lies about 0.07 from the converged xy, the strata's fixed wavelengths
  // acting as a three-point quadrature).
  const Estimate first = wall(render(scene, settings_for(stratified, 32, 1, 5)).film);
  const auto [x1, y1] = chromaticity(first);
  const auto [xr, yr] = chromaticity(reference);
  std::printf("[ strata ] first-sample xy (%.4f, %.4f), converged (%.4f, %.4f)\n", x1, y1, xr, yr);
  EXPECT_TRUE(std::isfinite(x1) && std::isfinite(y1));
}

}  // namespace
}  // namespace prism

namespace prism {
namespace {

TEST(Integrator, BaseColourTextureModulatesReflectance) {
  // A floor whose base colour texture is red on the left half and green on the right,
  // lit by a white directional light straight down, direct light only: each half's
  // radiance is ρ/π · E in its own colour (RGB transport; finest mip level at this scale).
  Light sun;
  sun.type = LightType::directional;
  sun.direction = Vec3f(0, -1, 0);
  sun.intensity = 100.0f;
  Scene scene = lit_floor(sun);
  scene.meshes[0].uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  TextureImage texture;
  texture.name = "red-green";
  texture.width = 16;  // texels 0–7 red, 8–15 green
  texture.height = 1;
  texture.channels = 3;
  for (int i = 0; i < 16; ++i) texture.texels.insert(texture.texels.end(), {i < 8 ? 1.0f : 0.0f, i < 8 ? 0.0f : 1.0f, 0.0f});
  texture.wrap_u = texture.wrap_v = TextureWrap::clamp;
  scene.textures.push_back(texture);
  scene.materials[0].base_color = Vec3f(1.0f);
  scene.materials[0].base_color_texture = 0;
  scene.camera.fov_degrees = 90.0f;
  scene.camera.eye = Vec3f(0, 90, 0);  // sees x in [-90, 90]: u in [0.05, 0.95]
  RenderSettings s = settings_for(all_modes()[0].transport, 16, 4);
  s.path.max_depth = 1;
  const Film film = render(scene, s).film;
  const double lit = 100.0 / std::numbers::pi;  // ρ = 1 in the texel's channel
  // The camera looks down with +z up in the image, so world x grows to the image's left:
  // the left block sees u ≈ 0.72–0.89 (green texels), the right u ≈ 0.11–0.28 (red), away
  // from the bilinear blend around u = 0.5.
  const Estimate left = block(film, 1, 6, 4, 10), right = block(film, 12, 6, 15, 10);
  EXPECT_NEAR(left.mean.y, lit, 1e-3 * lit);  // u > 0.5: green texel
  EXPECT_NEAR(left.mean.x, 0.0, 1e-6);
  EXPECT_NEAR(right.mean.x, lit, 1e-3 * lit);  // u < 0.5: red texel
  EXPECT_NEAR(right.mean.y, 0.0, 1e-6);
}

}  // namespace
}  // namespace prism

namespace prism {
namespace {

Scene floor_under_sky(int texture_rows_lit) {
  Light sky;
  sky.type = LightType::environment;
  sky.intensity = 10.0f;  // nits
  Scene scene = lit_floor(sky);
  scene.camera.eye = Vec3f(0, 1, 0);
  scene.camera.fov_degrees = 60.0f;
  if (texture_rows_lit > 0) {
    // 8×4 equirect: the top `texture_rows_lit` rows (from +y down) are 1, the rest 0.
    TextureImage t;
    t.name = "sky";
    t.width = 8;
    t.height = 4;
    t.channels = 3;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 8; ++x) t.texels.insert(t.texels.end(), 3, y < texture_rows_lit ? 1.0f : 0.0f);
    scene.textures.push_back(t);
    scene.lights[0].environment_texture = 0;
  }
  return scene;
}

// The floor's radiance ρ/π ∫ L(θ) cos θ dω = 2ρ ∫₀^{π/2} L(θ) sin θ cos θ dθ under
// floor_under_sky(2): the 8×4 map filtered bilinearly (scene/environment_lookup.h) is
// L = 10 nits down to the second row's centre, θ = 3π/8, then falls linearly to 0 at the
// third row's centre, 5π/8: L = 10 (5/2 − 4θ/π) there. With ∫ sin θ cos θ dθ = sin²θ / 2
// and ∫ θ sin θ cos θ dθ = −θ cos 2θ / 4 + sin 2θ / 8:
double floor_radiance_under_two_lit_rows() {
  constexpr double rho = 0.5, lit = 10.0, pi = std::numbers::pi, a = 3.0 * pi / 8.0, b = pi / 2.0;
  const auto sc = [](double t) { return std::sin(t) * std::sin(t) / 2.0; };
  const auto t_sc = [](double t) { return -t * std::cos(2.0 * t) / 4.0 + std::sin(2.0 * t) / 8.0; };
  return 2.0 * rho * lit * (sc(a) + 2.5 * (sc(b) - sc(a)) - 4.0 / pi * (t_sc(b) - t_sc(a)));  // 4.87534
}

TEST(Integrator, EnvironmentLightsTheFloorAnalytically) {
  // A grey floor (ρ = 0.5) under a sky of L = 10 nits on its whole upper hemisphere sees
  // ρ L (∫ L cos θ dω = π L, times ρ/π); under a map whose top half is lit and bottom half
  // black, the value above (the filtered map fades to black across the horizon). Every
  // estimator and mode agrees with it: 5σ plus 1e-4 relative.
  for (int rows : {0, 2}) {
    const Scene scene = floor_under_sky(rows);
    const double expected = rows == 0 ? 5.0 : floor_radiance_under_two_lit_rows();
    for (const ModeCase& m : {all_modes()[0], all_modes()[5], all_modes().back()})
      for (LightEstimator est : {LightEstimator::mis, LightEstimator::nee_only, LightEstimator::bsdf_only}) {
        RenderSettings s = settings_for(m.transport, 8, 64, 11);
        s.path.max_depth = 1;
        s.path.estimator = est;
        const Estimate e = whole_film(render(scene, s).film);
        EXPECT_NEAR(e.mean.y, expected, 5.0 * std::sqrt(e.variance.y) + 5e-4)
            << "rows " << rows << " " << describe(m.transport) << " estimator " << static_cast<int>(est);
      }
  }
}

TEST(Integrator, CameraSeesTheEnvironmentDirectly) {
  Scene scene = floor_under_sky(0);
  scene.camera.target = Vec3f(0, 2, 1);  // looking up: only sky
  for (const ModeCase& m : {all_modes()[0], all_modes()[5]}) {
    const Estimate e = whole_film(render(scene, settings_for(m.transport, 4, 16)).film);
    EXPECT_NEAR(e.mean.y, 10.0, 5.0 * std::sqrt(e.variance.y) + 1e-3) << describe(m.transport);
  }
}

}  // namespace
}  // namespace prism
