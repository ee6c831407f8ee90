// The viewer's render worker keeps the prepared scene (flattened geometry and BVH) across
// restarts: camera, material and light edits restart accumulation without rebuilding it.
#include "prism/viewer/render_session.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "prism/scene/builtin_scenes.h"

namespace prism::viewer {
namespace {

RenderRequest small_request(const Scene& scene) {
  RenderRequest r;
  r.camera = scene.camera;
  r.materials = scene.materials;
  r.lights = scene.lights;
  r.settings.width = 32;
  r.settings.height = 32;
  r.settings.samples_per_pixel = 2;
  r.settings.samples_per_pass = 1;
  r.settings.threads = 1;
  return r;
}

// The finished frame of `generation`, or null after a generous timeout (the render of a
// 32×32 film takes milliseconds; the timeout only guards against a hang).
std::shared_ptr<const FilmFrame> wait_finished(const RenderSession& session, std::uint64_t generation) {
  for (int i = 0; i < 6000; ++i) {
    const auto frame = session.latest();
    if (frame && frame->generation == generation && frame->finished) return frame;
    if (session.error()) return nullptr;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return nullptr;
}

double mean_value(const FilmFrame& frame) {
  double sum = 0.0;
  for (float v : frame.film.rgb) sum += v;
  return sum / static_cast<double>(frame.film.rgb.size());
}

TEST(RenderSession, RestartsReuseThePreparedScene) {
  const Scene scene = make_cornell_box();
  RenderSession session(scene);
  RenderRequest request = small_request(scene);
  const auto first = wait_finished(session, session.restart(request));
  ASSERT_TRUE(first) << session.error().value_or("timeout");
  EXPECT_EQ(session.prepare_count(), 1);

  // A camera move and a material edit: both render, neither prepares the scene again.
  request.camera.eye = request.camera.eye + Vec3f(10.0f, 0.0f, 0.0f);
  ASSERT_TRUE(wait_finished(session, session.restart(request))) << session.error().value_or("timeout");
  for (Material& m : request.materials)
    if (!m.is_emissive()) m.base_color = Vec3f(0.0f);
  const auto black = wait_finished(session, session.restart(request));
  ASSERT_TRUE(black) << session.error().value_or("timeout");
  EXPECT_EQ(session.prepare_count(), 1);

  // The material edit reached the renderer: with black walls only the light and its
  // direct view remain, far below the lit box.
  EXPECT_LT(mean_value(*black), 0.5 * mean_value(*first));
}

// Bounces per pass: the worker also publishes films in the middle of passes, so a render
// of 2 passes shows more than 2 frames (`passes` counts every published frame).
TEST(RenderSession, BouncesPerPassPublishesFramesInsidePasses) {
  const Scene scene = make_cornell_box();
  RenderSession session(scene);
  RenderRequest request = small_request(scene);
  request.settings.bounces_per_pass = 1;
  const auto last = wait_finished(session, session.restart(request));
  ASSERT_TRUE(last) << session.error().value_or("timeout");
  EXPECT_EQ(last->spp, 2);
  EXPECT_GT(last->passes, 2);
}

TEST(RenderSession, AMaterialListOfTheWrongSizeIsAnErrorNotACrash) {
  const Scene scene = make_cornell_box();
  RenderSession session(scene);
  RenderRequest request = small_request(scene);
  request.materials.pop_back();
  const std::uint64_t g = session.restart(request);
  for (int i = 0; i < 6000 && !session.error(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(session.error());
  EXPECT_NE(session.error()->find("materials"), std::string::npos) << *session.error();
  // The session recovers with a valid request.
  ASSERT_TRUE(wait_finished(session, session.restart(small_request(scene)))) << session.error().value_or("timeout");
  EXPECT_GT(session.generation(), g);
}

}  // namespace
}  // namespace prism::viewer
