// The viewer's main loop (viewer_app.h): UI thread only. Rendering runs in RenderSession,
// the display pipeline in DisplayWorker; this loop moves data between them and the window.
#include "prism/viewer/viewer_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "prism/core/bounds.h"
#include "prism/core/parallel.h"
#include "prism/display/exposure.h"
#include "prism/sampling/pixel_sampler.h"
#include "prism/scene/camera_json.h"
#include "prism/scene/camera_selection.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/load_scene.h"
#include "prism/viewer/camera_input.h"
#include "prism/viewer/display_worker.h"
#include "prism/viewer/frame_stats.h"
#include "prism/viewer/image_save.h"
#include "prism/viewer/memory_monitor.h"
#include "prism/viewer/panels.h"
#include "prism/viewer/presenter.h"
#include "prism/viewer/render_session.h"
#include "prism/viewer/viewer_window.h"

namespace prism::viewer {
namespace {

constexpr int kContinuousSpp = 1 << 24;  // interactive renders run until restarted
constexpr double kFrameBudgetSeconds = 1.0 / 60.0;

double scene_diagonal(const Scene& scene) {
  Vec3f lo{1e30f}, hi{-1e30f};
  for (const TriangleMesh& m : scene.meshes)
    for (const Vec3f& p : m.positions)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
  const double d = length(Vec3d(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z));
  return std::isfinite(d) && d > 0 ? d : 1.0;
}

// The same view with its target moved along the viewing direction to the depth of the
// scene's centre, so that orbiting turns around the scene rather than around a point just
// in front of the lens (scene files often put the target one unit ahead).
Camera orbit_pivot_camera(const Scene& scene) {
  Camera c = scene.camera;
  Vec3d lo{1e300}, hi{-1e300};
  for (const TriangleMesh& m : scene.meshes)
    for (const Vec3f& p : m.positions)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min<double>(lo[a], p[a]);
        hi[a] = std::max<double>(hi[a], p[a]);
      }
  const Vec3d eye(c.eye.x, c.eye.y, c.eye.z);
  const Vec3d view = Vec3d(c.target.x, c.target.y, c.target.z) - eye;
  const double distance = length(view);
  if (!(distance > 0) || !(hi.x >= lo.x)) return c;
  const Vec3d dir = view / distance;
  const double depth = dot((lo + hi) * 0.5 - eye, dir);
  if (depth > distance) {
    const Vec3d t = eye + dir * depth;
    c.target = Vec3f(static_cast<float>(t.x), static_cast<float>(t.y), static_cast<float>(t.z));
  }
  return c;
}

std::string vec_text(const Vec3f& v) { return fmt::format("{:.4g},{:.4g},{:.4g}", v.x, v.y, v.z); }

class ViewerApp {
 public:
  ViewerApp(const ViewerOptions& options, Scene scene, ViewerWindow& window)
      : options_(options),
        scene_name_(scene.name),
        scene_cameras_(scene.cameras),
        window_(window),
        camera_input_(orbit_pivot_camera(scene), scene_diagonal(scene)),
        session_(scene) {
    // The first picture's defaults, shared with `prism render` (viewer_state.h), then the options.
    InitialControls initial = initial_controls(scene);
    render_ = std::move(initial.render);
    display_ = std::move(initial.display);
    RenderSettings& s = render_.settings;
    if (options.max_depth) s.path.max_depth = *options.max_depth;
    if (!options.sampler.empty()) s.path.sampler = *parse_sampler(options.sampler);  // checked by run_viewer
    if (!options.normal_mapping.empty())
      s.path.normal_mapping = *parse_normal_mapping(options.normal_mapping);  // checked by run_viewer
    s.samples_per_pass = std::max(options.samples_per_pass, 1);
    s.bounces_per_pass = options.bounces_per_pass;
    s.threads = options.threads;
    s.transport.kind = options.mode == "rgb" ? TransportKind::rgb : TransportKind::spectral;
    s.samples_per_pixel = options.frames > 0 ? options.frames * s.samples_per_pass : kContinuousSpp;
    render_.resolution_scale = std::clamp(options.resolution_scale, 0.125, 1.0);
    render_.camera = orbit_pivot_camera(scene);  // the same view, its orbit target at the scene's depth
    display_.settings.odt = display::parse_odt(options.odt);
    if (!options.rendering.empty()) display_.settings.rendering = display::parse_rendering(options.rendering);
    if (!options.view.empty()) display_.view = display::parse_debug_view(options.view);
    if (options.ev100) {
      display_.auto_exposure = false;
      display_.ev100 = *options.ev100;
    }
    save_.image_path = scene_name_ + "-view.png";
    save_.film_path = scene_name_ + "-view.exr";
    save_.camera_path = scene_name_ + "-camera.json";
  }

  int run() {
    int fb_w = 0, fb_h = 0;
    window_.framebuffer_size(fb_w, fb_h);
    log("ready window={}x{}", fb_w, fb_h);
    double work_s = 0;
    while (!window_.should_close()) {
      // Pace at about 60 Hz: wait for input only for what is left of the frame's budget,
      // so the waiting leaves the cores to the render threads.
      window_.wait_events(std::max(kFrameBudgetSeconds - work_s, 1e-4));
      const double dt = stats_.tick();
      const auto work_start = std::chrono::steady_clock::now();
      const bool done = frame(dt);
      work_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - work_start).count();
      stats_.add_work(work_s);
      if (done) break;
    }
    const MemoryFigures at_exit = MemoryMonitor().figures();  // read now, not the overlay's last second
    log("ui frames={} mean_ms={:.2f} p50_ms={:.2f} p95_ms={:.2f} max_ms={:.2f} work_mean_ms={:.2f} "
        "peak_memory_mib={:.0f}",
        stats_.frames(), stats_.mean_ms(), stats_.percentile_ms(50), stats_.percentile_ms(95),
        stats_.percentile_ms(100), stats_.work_mean_ms(), at_exit.peak_mib);
    return exit_status_;
  }

 private:
  template <class... Args>
  void log(fmt::format_string<Args...> format, Args&&... args) {
    if (!options_.log_events) return;
    std::fputs((fmt::format(format, std::forward<Args>(args)...) + "\n").c_str(), stdout);
    std::fflush(stdout);
  }

  void restart(const char* reason) {
    window_.framebuffer_size(fb_w_, fb_h_);
    RenderRequest request{render_.camera, render_.materials, render_.lights, render_.settings};
    request.settings.width = std::max(16, static_cast<int>(std::lround(fb_w_ * render_.resolution_scale)));
    request.settings.height = std::max(16, static_cast<int>(std::lround(fb_h_ * render_.resolution_scale)));
    const std::uint64_t g = session_.restart(request);
    log("restart generation={} reason={} film={}x{} normal_mapping={} scene_prepared={}", g, reason,
        request.settings.width, request.settings.height, normal_mapping_name(request.settings.path.normal_mapping),
        session_.prepare_count());
  }

  // One UI frame; true when the viewer should exit.
  bool frame(double dt) {
    int w = 0, h = 0;
    window_.framebuffer_size(w, h);
    if (w <= 0 || h <= 0) return false;  // minimised
    if (!started_ || w != fb_w_ || h != fb_h_) {
      restart(started_ ? "resize" : "start");
      started_ = true;
    }
    window_.begin_ui_frame();
    const CameraInputResult input = camera_input_.update(window_.handle(), render_.camera, std::min(w, h), dt);
    if (input.changed) {
      log("camera what={} eye={} target={}", input.what, vec_text(render_.camera.eye), vec_text(render_.camera.target));
      restart("camera");
    }
    if (input.quit) window_.request_close();
    build_ui(w);
    handle_saves();
    ImGui::Render();
    feed_display();
    return present(w, h);
  }

  void build_ui(int fb_width) {
    const std::shared_ptr<const FilmFrame> film = session_.latest();
    shown_ = display_worker_.latest();
    const float scale = ImGui::GetIO().FontGlobalScale;
    const float panel_w = 380.0f * scale;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(fb_width) - panel_w - 10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(panel_w, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("Prism")) {
      if (render_settings_panel(render_)) restart("render-settings");
      if (camera_panel(render_, scene_cameras_, camera_input_.initial())) restart("camera-panel");
      if (lights_panel(render_)) restart("lights");
      if (display_panel(display_, shown_.get())) {
        ++display_version_;
        log("display-change version={}", display_version_);
      }
      save_panel(save_, save_message_);
    }
    ImGui::End();
    std::string status = session_.error().value_or("");
    stats_overlay(film.get(), shown_.get(), stats_.recent(), memory_.figures(), status);
    if (film && film->serial != logged_serial_) {
      logged_serial_ = film->serial;
      log("pass generation={} spp={} passes={} elapsed_s={:.3f}", film->generation, film->spp, film->passes,
          film->elapsed_seconds);
    }
  }

  void handle_saves() {
    try {
      if (save_.save_image && shown_) {
        save_display_image(save_.image_path, *shown_, display_);
        save_message_ = "saved " + save_.image_path;
      }
      if (save_.save_film) {
        if (const auto film = session_.latest()) save_film_exr(save_.film_path, *film, scene_name_);
        save_message_ = "saved " + save_.film_path;
      }
      if (save_.save_camera) {
        write_camera_json(save_.camera_path, render_.camera);
        save_message_ = "saved " + save_.camera_path;
      }
    } catch (const std::exception& e) {
      save_message_ = e.what();
    }
    if (save_.save_image || save_.save_film || save_.save_camera) log("save {}", save_message_);
  }

  // Hands the display thread whatever changed: a new film or new controls; and the same
  // film again while auto exposure is still adapting toward the metered EV.
  void feed_display() {
    const std::shared_ptr<const FilmFrame> film = session_.latest();
    if (!film) return;
    // Until the restarted render's first pass arrives, keep showing the previous image.
    const bool adapting = shown_ && shown_->exposure_adapting && shown_->film_serial == submitted_serial_ &&
                          shown_->controls_version == submitted_version_ && !display_worker_.busy();
    if (film->serial == submitted_serial_ && display_version_ == submitted_version_ && !adapting) return;
    DisplayJob job;
    job.film = film;
    job.controls = display_;
    job.controls_version = display_version_;
    job.controls.settings.render_scale = render_.resolution_scale;
    display_worker_.submit(std::move(job));
    submitted_serial_ = film->serial;
    submitted_version_ = display_version_;
  }

  // HDR targets are shown as their SDR preview (display_worker.cpp), so the UI is always
  // drawn over the image by ImGui, as in SDR.
  bool present(int w, int h) {
    if (shown_ && (shown_->film_serial != uploaded_serial_ || shown_->controls_version != uploaded_version_ ||
                   shown_.get() != uploaded_frame_)) {
      presenter_.upload(shown_->width, shown_->height, shown_->rgba);
      uploaded_serial_ = shown_->film_serial;
      uploaded_version_ = shown_->controls_version;
      uploaded_frame_ = shown_.get();
    }
    presenter_.draw(w, h);
    window_.render_ui();
    const bool done = headless_done();
    if (done) write_screenshot(w, h);
    window_.swap();
    return done;
  }

  // Headless: the film has all its passes and the window shows exactly that film.
  bool headless_done() const {
    if (options_.frames <= 0) return false;
    const std::shared_ptr<const FilmFrame> film = session_.latest();
    if (!film || !film->finished || film->generation != session_.generation()) return false;
    return shown_ && shown_->film_serial == film->serial && shown_->controls_version == display_version_ &&
           uploaded_frame_ == shown_.get();
  }

  void write_screenshot(int w, int h) {
    if (options_.screenshot.empty()) return;
    const EncodedImage shot = Presenter::read_framebuffer(w, h);
    save_screenshot(options_.screenshot, shot);
    // Mean and spread of the code values, so scripts can check brightness without a decoder.
    double sum = 0, sum_sq = 0;
    for (const std::uint16_t v : shot.samples) {
      sum += v / 255.0;
      sum_sq += (v / 255.0) * (v / 255.0);
    }
    const double n = std::max<double>(1, static_cast<double>(shot.samples.size()));
    const double mean = sum / n;
    log("screenshot {} {}x{} mean={:.4f} stddev={:.4f}", options_.screenshot, w, h, mean,
        std::sqrt(std::max(0.0, sum_sq / n - mean * mean)));
  }

  ViewerOptions options_;
  std::string scene_name_;
  std::vector<Camera> scene_cameras_;
  ViewerWindow& window_;
  CameraInput camera_input_;
  RenderSession session_;
  DisplayWorker display_worker_;
  Presenter presenter_;
  FrameStats stats_;
  MemoryMonitor memory_;
  RenderControls render_;
  DisplayControls display_;
  SaveRequest save_;
  std::string save_message_;
  std::shared_ptr<const DisplayFrame> shown_;
  std::uint64_t display_version_ = 1;
  std::uint64_t submitted_serial_ = 0, submitted_version_ = 0;
  std::uint64_t uploaded_serial_ = 0, uploaded_version_ = 0, logged_serial_ = 0;
  const DisplayFrame* uploaded_frame_ = nullptr;
  int fb_w_ = 0, fb_h_ = 0;
  bool started_ = false;
  int exit_status_ = 0;
};

}  // namespace

int run_viewer(const ViewerOptions& options) {
  if (options.frames < 0) throw UsageError("--frames must be at least 1");
  if (!options.screenshot.empty() && options.frames <= 0) throw UsageError("--screenshot needs --frames N");
  if (options.mode != "spectral" && options.mode != "rgb") throw UsageError("--mode must be spectral or rgb");
  if (options.bounces_per_pass < 0) throw UsageError("--bounces-per-pass must be 0 (off) or more");
  if (!options.sampler.empty() && !parse_sampler(options.sampler))
    throw UsageError(fmt::format("unknown --sampler '{}' (independent, sobol, zsobol)", options.sampler));
  if (!options.normal_mapping.empty() && !parse_normal_mapping(options.normal_mapping))
    throw UsageError(fmt::format("unknown --normal-mapping '{}' ({})", options.normal_mapping, kNormalMappingNames));
  if (options.threads < 0) throw UsageError("--threads must be at least 1 (omit it to use all cores)");
  display::require_rendering_target(
      options.rendering.empty() ? display::kDefaultRendering : display::parse_rendering(options.rendering),
      display::parse_odt(options.odt));
  if (!options.view.empty()) display::parse_debug_view(options.view);
  // Loading, preparing the scene (BVH, mip pyramids) and the display's work keep to
  // --threads as well as the render.
  const ThreadLimit thread_limit(options.threads);
  // The display check comes first: without one there is nothing to show the scene in.
  ViewerWindow window(options.window_width, options.window_height, "Prism - " + options.scene);
  Scene scene = load_scene(options.scene, LoadOptions{.allow_external_paths = options.allow_external_paths,
                                                      .material_variant = options.material_variant});
  if (!options.camera.empty()) select_camera(scene, options.camera);
  apply_environment_override(scene, options.environment, LoadOptions{.allow_external_paths = true});
  if (const auto warning = no_emitters_warning(scene)) fmt::print(stderr, "prism: warning: {}\n", *warning);
  ViewerApp app(options, std::move(scene), window);
  return app.run();
}

}  // namespace prism::viewer
