// The viewer's normal debug view shows the film's normal AOV as 0.5 + 0.5·N (issue 6).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "prism/scene/builtin_scenes.h"
#include "prism/viewer/display_worker.h"
#include "prism/viewer/render_session.h"

namespace prism::viewer {
namespace {

std::shared_ptr<const FilmFrame> finished_frame(RenderSession& session, const RenderRequest& request) {
  session.restart(request);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto frame = session.latest(); frame && frame->finished) return frame;
    if (session.error()) return nullptr;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return nullptr;
}

TEST(ViewerNormalView, ShowsTheFilmsNormalAov) {
  const Scene scene = make_cornell_box();
  RenderSession session(scene);
  RenderRequest request{scene.camera, scene.materials, scene.lights, {}};
  request.settings.width = 32;
  request.settings.height = 32;
  request.settings.samples_per_pixel = 2;
  request.settings.aovs.normal = true;
  const auto frame = finished_frame(session, request);
  ASSERT_TRUE(frame) << session.error().value_or("timed out");
  ASSERT_TRUE(frame->normals);
  ASSERT_EQ(frame->normals->rgb.size(), 3u * 32 * 32);

  DisplayJob job;
  job.film = frame;
  job.controls_version = 1;
  job.controls.view = display::DebugView::normal;
  const DisplayFrame shown = compute_display_frame(job);
  ASSERT_TRUE(shown.error.empty()) << shown.error;
  ASSERT_EQ(shown.width, 32);
  for (std::size_t i = 0; i < 32u * 32u; ++i)
    for (int c = 0; c < 3; ++c) {
      const float n = frame->normals->rgb[3 * i + c];
      ASSERT_EQ(shown.rgba[4 * i + c], std::lround(std::clamp(0.5f + 0.5f * n, 0.0f, 1.0f) * 255.0f)) << i;
    }
  // Row 29, column 8 sees only floor, left of the short block: normal (0, 1, 0).
  const std::size_t floor = 29 * 32 + 8;
  EXPECT_EQ(shown.rgba[4 * floor + 1], 255);
  EXPECT_EQ(shown.rgba[4 * floor + 0], 128);
  EXPECT_EQ(shown.rgba[4 * floor + 2], 128);

  // A film without the AOV gives a message, not a crash or a stale picture.
  auto bare = std::make_shared<FilmFrame>(*frame);
  bare->normals.reset();
  job.film = bare;
  EXPECT_NE(compute_display_frame(job).error.find("normal AOV"), std::string::npos);
}

}  // namespace
}  // namespace prism::viewer
