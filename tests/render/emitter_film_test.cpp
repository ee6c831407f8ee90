// A directly seen emitter of known RGB films as that RGB, in every transport mode and
// working space: the camera sits inside a black enclosure whose walls emit the pbrt-v4
// Cornell box's light colour, `rgb L [17 12 4]` (sRGB primaries), at that colour's own
// luminance, so every pixel sees exactly that radiance. RGB transport has no noise here;
// spectral transport estimates the film's XYZ integral from a few wavelengths a sample, so
// the image mean is compared within 0.1 % and within four of its standard errors (the
// emission rule itself is exact to 1e-4: tests/color/emission_spectrum_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/render/renderer.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

constexpr Vec3d kLightRgb{17.0, 12.0, 4.0};

Scene enclosure_emitting_light_rgb() {
  Scene scene = test::make_emitting_enclosure(0.0f, 1.0f);
  Material& wall = scene.materials[0];
  wall.emission.color = Vec3f(kLightRgb / kLightRgb.x);
  wall.emission.luminance_nits = static_cast<float>((color::color_space("srgb").rgb_to_xyz * kLightRgb).y);
  wall.emission.two_sided = true;
  return scene;
}

struct ImageMean {
  Vec3d mean, standard_error;
};

// The image's mean in working RGB: a spectral film holds E-relative CIE XYZ, which the
// output adapts to the working white (color::spectral_xyz_to_rgb_matrix).
ImageMean image_mean(const Film& film, const Mat3& film_to_working) {
  ImageMean m;
  const auto n = static_cast<double>(film.pixel_count());
  for (std::size_t p = 0; p < film.pixel_count(); ++p) {
    m.mean += film_to_working * film.mean(p) / n;
    m.standard_error += film.variance_of_mean(p, film_to_working) / (n * n);
  }
  for (int c = 0; c < 3; ++c) m.standard_error[c] = std::sqrt(m.standard_error[c]);
  return m;
}

void expect_films_light_rgb(const TransportSettings& transport, const std::string& label) {
  RenderSettings s;
  s.width = s.height = 32;
  s.samples_per_pixel = 64;
  s.transport = transport;
  s.aovs.variance = true;  // the variance of each working-space channel of a spectral film
  const RenderResult r = render(enclosure_emitting_light_rgb(), s);
  const color::ColorSpace& working = color::color_space(transport.working_space);
  const Vec3d expected = color::conversion_matrix(color::color_space("srgb"), working) * kLightRgb;
  const Mat3 film_to_working =
      transport.kind == TransportKind::spectral ? color::spectral_xyz_to_rgb_matrix(working) : Mat3::identity();
  const ImageMean m = image_mean(r.film, film_to_working);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(m.mean[c] / expected[c], 1.0, 1e-3) << label << " channel " << c << ": " << m.mean[c];
    EXPECT_LT(std::abs(m.mean[c] - expected[c]), 4.0 * m.standard_error[c] + 1e-6 * expected[c])
        << label << " channel " << c;
  }
}

TEST(EmitterFilm, DirectlySeenLightOfKnownRgbFilmsAsThatRgb) {
  for (const std::string space : {"srgb", "acescg", "rec2020"}) {
    TransportSettings rgb;
    rgb.kind = TransportKind::rgb;
    rgb.working_space = space;
    expect_films_light_rgb(rgb, "rgb " + space);
    for (const color::WavelengthStrategy strategy :
         {color::WavelengthStrategy::cosh, color::WavelengthStrategy::hero}) {
      TransportSettings spectral;
      spectral.kind = TransportKind::spectral;
      spectral.working_space = space;
      spectral.wavelength_strategy = strategy;
      expect_films_light_rgb(spectral, "spectral " + space);
    }
  }
}

}  // namespace
}  // namespace prism
