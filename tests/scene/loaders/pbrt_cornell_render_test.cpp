// The pbrt-v4 Cornell box renders like the built-in one: image means agree within 5σ of
// the films' own variance estimates (independent seeds, so the renders are independent).
#include <gtest/gtest.h>

#include <cmath>

#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/scene/load_scene.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

using test::BlockEstimate;

BlockEstimate cornell_block(const Film& film, int x0, int y0, int x1, int y1) {
  return test::block_estimate(film, x0, y0, x1, y1);
}

TEST(PbrtLoader, CornellBoxRendersLikeTheBuiltIn) {
  const Scene pbrt = load_scene(std::string(PRISM_SOURCE_DIR) + "/data/scenes/cornell-box.pbrt");
  const Scene builtin = make_builtin_scene("cornell-box");
  RenderSettings s;
  s.width = 32;
  s.height = 32;
  s.samples_per_pixel = 32;
  s.path.max_depth = 5;
  s.seed = 1;
  const RenderResult a = render(pbrt, s);
  s.seed = 2;
  const RenderResult b = render(builtin, s);
  // Whole image and 2×2 quadrants (which catch a mirrored image), 3 channels each: 15
  // comparisons at 5σ raise a false alarm with probability below 1e-5.
  const int h = s.width / 2;
  const int regions[5][4] = {{0, 0, 32, 32}, {0, 0, h, h}, {h, 0, 32, h}, {0, h, h, 32}, {h, h, 32, 32}};
  for (const auto& r : regions) {
    const BlockEstimate ea = cornell_block(a.film, r[0], r[1], r[2], r[3]);
    const BlockEstimate eb = cornell_block(b.film, r[0], r[1], r[2], r[3]);
    for (int c = 0; c < 3; ++c) {
      const double sigma = std::sqrt(ea.variance[c] + eb.variance[c]);
      EXPECT_GT(ea.mean[c], 0.0);
      EXPECT_LE(std::abs(ea.mean[c] - eb.mean[c]), 5.0 * sigma + 1e-9)
          << "region (" << r[0] << "," << r[1] << ") channel " << c << ": " << ea.mean[c] << " vs " << eb.mean[c];
    }
  }
}

}  // namespace
}  // namespace prism
