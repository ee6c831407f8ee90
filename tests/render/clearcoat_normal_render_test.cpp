// The coat's own normal map (clearcoat_normal_texture, glTF's clearcoatNormalTexture):
// over a black base only the coat reflects, so bending the coat alone must give the image
// that bending the whole surface (normal_texture) gives, and both must move the highlight.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/render/renderer.h"
#include "support/test_scenes.h"

namespace prism {
namespace {

constexpr int kSize = 48;

// A 1×1 tangent-space normal map tilted `tilt_deg` from the normal towards +u.
TextureImage tilted_normal_texel(double tilt_deg) {
  const double t = tilt_deg * std::numbers::pi / 180.0;
  TextureImage image;
  image.name = "tilt";
  image.width = image.height = 1;
  image.channels = 3;
  image.texels = {static_cast<float>(0.5 + 0.5 * std::sin(t)), 0.5f, static_cast<float>(0.5 + 0.5 * std::cos(t))};
  return image;
}

// A black diffuse floor (uv: u along world x) under a coat of roughness 0.2, seen from 5
// units above, lit by a point light 2 units above the centre; `coat_map`: the tilt goes on
// the coat alone, else on the whole surface. RGB transport, direct light only.
Film render_coated_floor(double tilt_deg, bool coat_map) {
  Material m;
  m.type = MaterialType::diffuse;
  m.base_color = Vec3f(0.0f);
  m.clearcoat = 1.0f;
  m.clearcoat_roughness = 0.2f;
  if (tilt_deg != 0.0) (coat_map ? m.clearcoat_normal_texture : m.normal_texture) = 0;
  Scene scene = test::make_bulb_lit_uv_floor(m);
  if (tilt_deg != 0.0) scene.textures.push_back(tilted_normal_texel(tilt_deg));
  return render(scene, test::direct_light_rgb_settings(kSize)).film;
}

double centroid_x(const Film& film) {
  double sum = 0.0, x_sum = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double v = film.mean(static_cast<std::size_t>(y) * kSize + x).y;
      sum += v, x_sum += v * x;
    }
  return x_sum / sum;
}

TEST(ClearcoatNormalRender, CoatNormalMapBendsTheCoatAsANormalMapBendsTheSurface) {
  const double flat = centroid_x(render_coated_floor(0.0, true));
  EXPECT_NEAR(flat, (kSize - 1) / 2.0, 0.5);  // symmetric set-up
  for (const double tilt : {15.0, -15.0}) {
    const Film coat = render_coated_floor(tilt, true), surface = render_coated_floor(tilt, false);
    const double shift = centroid_x(coat) - flat;
    std::printf("tilt %+.0f°: highlight centroid moved %.2f px (coat map), %.2f px (surface map)\n", tilt, shift,
                centroid_x(surface) - flat);
    // 15° bends the mirror direction by 30°: several pixels at this field of view; the sign
    // follows the tilt.
    EXPECT_GT(std::abs(shift), 4.0) << tilt;
    // A normal leaning towards +x faces the eye and the light (both above the centre) from
    // world x < 0, where the highlight moves; image x is world −x (camera up +z, looking down).
    EXPECT_EQ(shift > 0.0, tilt > 0.0) << tilt;
    // Same image up to float rounding, and to which reflections count as below the surface
    // (the coat map drops those below the unmapped surface, the surface map those below
    // the mapped one): none here, with every light direction within 30° of the normal.
    double diff = 0.0, total = 0.0;
    for (std::size_t p = 0; p < static_cast<std::size_t>(kSize * kSize); ++p) {
      diff += std::abs(coat.mean(p).y - surface.mean(p).y);
      total += surface.mean(p).y;
    }
    EXPECT_LT(diff, 1e-4 * total) << tilt;
  }
}

}  // namespace
}  // namespace prism
