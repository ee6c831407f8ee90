// The repository's own scene files light what they show: with the environment (sky) removed,
// a small render of each scene that has emissive geometry is not black. One-sided emitters
// wound the wrong way round shine away from everything; four bench scenes once did (their
// area light faced the sky) and were lit by the sky alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "support/film_statistics.h"

namespace prism {
namespace {

TEST(SceneFiles, EmissiveGeometryLightsTheScene) {
  int checked = 0;
  for (const char* folder : {"bench/scenes", "data/scenes"}) {
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(PRISM_SOURCE_DIR) / folder)) {
      if (entry.path().extension() != ".json") continue;
      Scene scene = load_scene(entry.path().string());
      const bool emissive = std::any_of(scene.materials.begin(), scene.materials.end(),
                                        [](const Material& m) { return m.is_emissive(); });
      if (!emissive) continue;
      std::erase_if(scene.lights, [](const Light& l) { return l.type == LightType::environment; });
      RenderSettings s;
      s.width = 32;
      s.height = 16;
      s.samples_per_pixel = 4;
      s.path.max_depth = 3;
      s.transport.kind = TransportKind::rgb;
      const Film film = render(scene, s).film;
      const double y = test::block_estimate(film, 0, 0, film.width(), film.height()).mean.y;
      // Any light that reaches a surface the camera sees gives a positive mean; the exact
      // amount does not matter here.
      EXPECT_GT(y, 0.0) << entry.path().filename() << ": its emitters light nothing the camera sees";
      ++checked;
    }
  }
  EXPECT_GE(checked, 8);  // the bench scenes with area lights, material-test, dispersion-prism
}

}  // namespace
}  // namespace prism
