// prism_first_picture_exposure: measures issue 47's exposure goal on the first picture of
// each scene named on the command line. For `prism render`'s first render (its defaults,
// render/first_picture.h: the film metered with camera-ray coverage) and for the viewer's
// first frame (viewer_state.h initial_controls: one pass of 1 spp at a 1280×720 window,
// metered by the display thread with the depth AOV's coverage), it prints the EV100 and the
// median displayed luminance (relative luminance of the decoded SDR output over the pixels
// that see a surface, display/exposure_metering.h median_displayed_luminance), whether both
// lie in [5 %, 30 %] of SDR white, and whether the two EVs agree within 0.3 EV. The view's
// median is taken on the rendered film shown at the view's first-frame EV (what its exposure
// makes of the picture); the median of the 1-spp frame itself is printed beside it, since a
// 1-spp frame's per-pixel median mostly measures its noise (env-lit scenes: most pixels of
// a single sample miss the bright parts of the map).
//
//   prism_first_picture_exposure [--spp N] [--environment MAP] SCENE...
// scripts/first-picture-exposure.sh runs it over every built-in, bench and glTF scene.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "prism/core/error.h"
#include "prism/display/exposure_metering.h"
#include "prism/render/camera_coverage.h"
#include "prism/render/first_picture.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/load_scene.h"
#include "prism/viewer/display_worker.h"
#include "prism/viewer/render_session.h"

namespace {

using namespace prism;

struct Measured {
  double ev100 = 0, median = 0;
};

struct Rendered {
  Measured measured;
  ImageRgbF film;
  color::ColorSpace film_space;
  std::vector<float> coverage;
};

double displayed_median(const ImageRgbF& film, const color::ColorSpace& space, const std::vector<float>& coverage,
                        double ev100) {
  display::DisplaySettings ds;
  ds.exposure_ev100 = ev100;
  const display::DisplayImage shown = display::apply_display_pipeline(film, space, ds);
  return display::median_displayed_luminance(shown.nits, shown.primaries, shown.white_nits, coverage);
}

Rendered measure_render(const Scene& scene, int spp) {
  const FirstPicture first = first_picture_defaults(scene);
  RenderSettings settings;
  settings.width = first.width;
  settings.height = first.height;
  settings.samples_per_pixel = scene.default_spp > 0 ? scene.default_spp : spp;
  settings.path = first.path;
  settings.transport = first.transport;
  const PreparedScene prepared(scene);
  const RenderResult result = render(prepared, settings, RenderHooks{});
  Rendered r;
  r.measured.ev100 = first.camera_ev100
                         ? *first.camera_ev100
                         : meter_rendered_film(prepared, result.film, result.film_space, first.metering).ev100;
  r.film = ImageRgbF{settings.width, settings.height, result.film.mean_rgb()};
  r.film_space = result.film_space;
  r.coverage = camera_ray_coverage(prepared, settings.width, settings.height);
  r.measured.median = displayed_median(r.film, r.film_space, r.coverage, r.measured.ev100);
  return r;
}

Measured measure_view(const Scene& scene) {
  viewer::InitialControls initial = viewer::initial_controls(scene);
  viewer::RenderRequest request{initial.render.camera, initial.render.materials, initial.render.lights,
                                initial.render.settings};
  request.settings.width = 1280;
  request.settings.height = 720;
  request.settings.samples_per_pixel = 1;
  viewer::RenderSession session(scene);
  session.restart(request);
  std::shared_ptr<const viewer::FilmFrame> frame;
  while (!(frame = session.latest()) || !frame->finished) {
    if (const auto e = session.error()) throw Error(*e);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  viewer::DisplayJob job;
  job.film = frame;
  job.controls = initial.display;
  const viewer::DisplayFrame shown = viewer::compute_display_frame(job);
  if (!shown.error.empty()) throw Error(shown.error);
  return {shown.ev100, display::median_displayed_luminance(shown.image->nits, shown.image->primaries,
                                                           shown.image->white_nits, frame->coverage)};
}

}  // namespace

int main(int argc, char** argv) {
  int spp = 64;
  EnvironmentOverride environment;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc) spp = std::stoi(argv[++i]);
    else if (a == "--environment" && i + 1 < argc) environment.source = argv[++i];
    else scenes.push_back(a);
  }
  std::printf("| scene | environment | render EV100 | render median | view EV100 | view median | ΔEV | goal | "
              "1-spp frame median |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  for (const std::string& name : scenes) {
    try {
      Scene scene = load_scene(name, LoadOptions{.allow_external_paths = true});
      apply_environment_override(scene, environment, LoadOptions{.allow_external_paths = true});
      const Rendered rendered = measure_render(scene, spp);
      const Measured r = rendered.measured;
      const Measured first_frame = measure_view(scene);
      const Measured v{first_frame.ev100,
                       displayed_median(rendered.film, rendered.film_space, rendered.coverage, first_frame.ev100)};
      const auto in_goal = [](double m) { return m >= 0.05 && m <= 0.30; };
      const bool ok = in_goal(r.median) && in_goal(v.median) && std::abs(r.ev100 - v.ev100) <= 0.3;
      failures += ok ? 0 : 1;
      const std::string env = environment.source.empty() ? "scene's" : environment.source.substr(
                                                                            environment.source.find_last_of('/') + 1);
      const std::string short_name = name.substr(name.find_last_of('/') + 1);
      std::printf("| %s | %s | %.2f | %.1f %% | %.2f | %.1f %% | %+.2f | %s | %.1f %% |\n", short_name.c_str(),
                  env.c_str(), r.ev100, 100 * r.median, v.ev100, 100 * v.median, v.ev100 - r.ev100,
                  ok ? "met" : "MISSED", 100 * first_frame.median);
    } catch (const std::exception& e) {
      std::printf("| %s | error: %s |\n", name.c_str(), e.what());
      ++failures;
    }
    std::fflush(stdout);
  }
  return failures == 0 ? 0 : 1;
}
