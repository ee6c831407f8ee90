// The integrator's plain diffuse path (WavefrontIntegrator::shade_surface<true>) against
// its general path: the Cornell box, whose materials are all plain diffuse, rendered as it
// is and with every material made to take the general path by a texture its lobe does not
// read (a metallic-roughness texture: a Lambertian lobe has no roughness and no metal).
// The two images must be the same bits, in every transport mode and estimator.
#include <gtest/gtest.h>

#include <string>

#include "prism/render/material_bsdf.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using test::films_identical;

// A grey 1×1 texture: where it were read it would halve roughness and metallic.
TextureImage grey_texel() {
  TextureImage t;
  t.name = "grey";
  t.width = 1;
  t.height = 1;
  t.channels = 3;
  t.texels = {0.5f, 0.5f, 0.5f};
  return t;
}

TEST(PlainDiffuseRender, SameImageAsTheGeneralPath) {
  const Scene plain = make_cornell_box();
  for (const Material& m : plain.materials) ASSERT_TRUE(is_plain_diffuse(m)) << m.name;
  Scene general = plain;
  general.textures.push_back(grey_texel());
  for (Material& m : general.materials) {
    m.metallic_roughness_texture = 0;
    ASSERT_FALSE(is_plain_diffuse(m)) << m.name;
  }

  struct Case {
    TransportKind kind;
    int wavelengths;
    LightEstimator estimator;
  };
  for (const Case c : {Case{TransportKind::spectral, 4, LightEstimator::mis},
                       Case{TransportKind::spectral, 8, LightEstimator::nee_only},
                       Case{TransportKind::spectral, 3, LightEstimator::bsdf_only},
                       Case{TransportKind::rgb, 3, LightEstimator::mis}}) {
    RenderSettings s;
    s.width = 24;
    s.height = 20;
    s.samples_per_pixel = 6;
    s.seed = 5;
    s.threads = 1;
    s.transport.kind = c.kind;
    s.transport.wavelengths = c.wavelengths;
    s.path.estimator = c.estimator;
    const std::string label = std::string(c.kind == TransportKind::rgb ? "rgb" : "spectral") + " " +
                              std::to_string(c.wavelengths) + ", estimator " +
                              std::to_string(static_cast<int>(c.estimator));
    const RenderResult a = render(plain, s);
    const RenderResult b = render(general, s);
    EXPECT_GT(a.film.counts()[0], 0u) << label;
    EXPECT_TRUE(films_identical(a.film, b.film)) << label << ": the plain and the general path differ";
  }
}

}  // namespace
}  // namespace prism
