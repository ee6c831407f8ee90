// The first picture of the Cornell box (issue 47's goal, held by a fast regression test):
// `prism render`'s path (render/first_picture.h: the film metered with camera-ray coverage)
// and the viewer's first frame (viewer_state.h initial_controls, a 1-spp film, the display
// thread's metering with the depth AOV's coverage) both put the median displayed luminance of
// the pixels that see something between 5 % and 30 % of SDR white, and agree within 0.3 EV.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "prism/display/exposure_metering.h"
#include "prism/render/first_picture.h"
#include "prism/render/camera_coverage.h"
#include "prism/scene/builtin_scenes.h"
#include "prism/viewer/display_worker.h"
#include "prism/viewer/render_session.h"

namespace prism::viewer {
namespace {

std::shared_ptr<const FilmFrame> first_frame(RenderSession& session, const RenderRequest& request) {
  session.restart(request);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto frame = session.latest(); frame && frame->finished) return frame;
    if (session.error()) return nullptr;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return nullptr;
}

struct Picture {
  double ev100 = 0, median = 0;
};

// `prism render cornell-box` at 128², 16 spp (the goal is about exposure, not noise).
Picture render_first_picture(const Scene& scene) {
  const FirstPicture first = first_picture_defaults(scene);
  RenderSettings settings;
  settings.width = settings.height = 128;
  settings.samples_per_pixel = 16;
  settings.path = first.path;
  settings.transport = first.transport;
  const PreparedScene prepared(scene);
  const RenderResult result = render(prepared, settings, RenderHooks{});
  const double ev = meter_rendered_film(prepared, result.film, result.film_space, first.metering).ev100;
  display::DisplaySettings ds;
  ds.exposure_ev100 = ev;
  const display::DisplayImage shown = display::apply_display_pipeline(
      ImageRgbF{128, 128, result.film.mean_rgb()}, result.film_space, ds);
  const std::vector<float> coverage = camera_ray_coverage(prepared, 128, 128);
  return {ev, display::median_displayed_luminance(shown.nits, shown.primaries, shown.white_nits, coverage)};
}

TEST(FirstPictureExposure, CornellBoxRenderAndViewerFirstFrameShowMidTones) {
  const Scene scene = make_cornell_box();
  const Picture render = render_first_picture(scene);
  // Today's figure without metering was 1.6 % (no exposure applied).
  EXPECT_GE(render.median, 0.05);
  EXPECT_LE(render.median, 0.30);

  // The viewer's first frame: its initial controls, a 16:9 window's film, one pass of 1 spp.
  InitialControls initial = initial_controls(scene);
  RenderRequest request{initial.render.camera, initial.render.materials, initial.render.lights,
                        initial.render.settings};
  request.settings.width = 160;
  request.settings.height = 90;
  request.settings.samples_per_pixel = 1;
  RenderSession session(scene);
  const auto frame = first_frame(session, request);
  ASSERT_TRUE(frame) << session.error().value_or("timed out");
  ASSERT_EQ(frame->coverage.size(), 160u * 90u);
  DisplayJob job;
  job.film = frame;
  job.controls = initial.display;
  const DisplayFrame shown = compute_display_frame(job);
  ASSERT_TRUE(shown.error.empty()) << shown.error;
  ASSERT_TRUE(shown.metered_ev100);
  EXPECT_EQ(shown.ev100, *shown.metered_ev100);  // the first frame is metered at once
  EXPECT_FALSE(shown.exposure_adapting);
  const double view_median = display::median_displayed_luminance(shown.image->nits, shown.image->primaries,
                                                                 shown.image->white_nits, frame->coverage);
  EXPECT_GE(view_median, 0.05);
  EXPECT_LE(view_median, 0.30);
  EXPECT_NEAR(shown.ev100, render.ev100, 0.3);

  // Later frames adapt from what was shown toward the meter, without jumping.
  job.shown_ev100 = shown.ev100 + 2.0;
  job.seconds_since_shown = 0.1;
  const DisplayFrame next = compute_display_frame(job);
  EXPECT_TRUE(next.exposure_adapting);
  EXPECT_GT(next.ev100, shown.ev100);
  EXPECT_LT(next.ev100, shown.ev100 + 2.0);
}

TEST(FirstPictureExposure, HdrTargetShowsTheSdrPreviewAndKeepsTheHdrImage) {
  const Scene scene = make_cornell_box();
  InitialControls initial = initial_controls(scene);
  RenderRequest request{initial.render.camera, initial.render.materials, initial.render.lights,
                        initial.render.settings};
  request.settings.width = request.settings.height = 48;
  request.settings.samples_per_pixel = 2;
  RenderSession session(scene);
  const auto frame = first_frame(session, request);
  ASSERT_TRUE(frame) << session.error().value_or("timed out");
  DisplayJob job;
  job.film = frame;
  job.controls = initial.display;
  job.controls.settings.odt = display::OdtId::rec2020_pq_1000nit;
  const DisplayFrame shown = compute_display_frame(job);
  ASSERT_TRUE(shown.error.empty()) << shown.error;
  // Saving writes the HDR output (PQ), the window shows the same picture's SDR target.
  ASSERT_TRUE(shown.image);
  EXPECT_EQ(shown.image->encoding, display::DisplayEncoding::pq);
  EXPECT_NE(shown.preview_note.find("SDR preview"), std::string::npos);
  display::DisplaySettings sdr = resolved_display_settings(job.controls);
  sdr.odt = display::OdtId::srgb_100nit;
  sdr.auto_exposure = false;
  sdr.exposure_ev100 = shown.ev100;
  const EncodedImage expected = display::quantise_display_image(
      display::apply_display_pipeline(frame->film, frame->film_space, sdr), 8, sdr.dither_seed);
  const EncodedImage pq = display::quantise_display_image(*shown.image, 8, sdr.dither_seed);
  std::size_t differs_from_pq = 0;
  for (std::size_t i = 0; i < 48u * 48u; ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(shown.rgba[4 * i + c], expected.samples[3 * i + c]) << i;
      differs_from_pq += shown.rgba[4 * i + c] != pq.samples[3 * i + c];
    }
  EXPECT_GT(differs_from_pq, 48u * 48u);  // not the PQ code values
}

}  // namespace
}  // namespace prism::viewer
