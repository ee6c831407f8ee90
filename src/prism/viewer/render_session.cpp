// The restartable render loop of the viewer (render_session.h).
#include "prism/viewer/render_session.h"

#include <chrono>
#include <exception>

#include "prism/render/aov_images.h"
#include "prism/render/color_context.h"

namespace prism::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

RenderSession::RenderSession(Scene scene) : scene_(std::move(scene)), worker_([this] { run(); }) {}

RenderSession::~RenderSession() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

std::uint64_t RenderSession::restart(const RenderRequest& request) {
  std::uint64_t generation;
  {
    std::lock_guard lock(mutex_);
    pending_ = request;
    generation = ++generation_;
    cancel_ = true;
    error_.reset();
  }
  wake_.notify_all();
  return generation;
}

std::shared_ptr<const FilmFrame> RenderSession::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

std::optional<std::string> RenderSession::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void RenderSession::publish(std::shared_ptr<const FilmFrame> frame) {
  std::lock_guard lock(mutex_);
  // A cancelled render's last film belongs to an old generation: never show it.
  if (frame->generation == generation_.load()) latest_ = std::move(frame);
}

void RenderSession::run() {
  for (;;) {
    RenderRequest request;
    std::uint64_t generation;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      request = std::move(*pending_);
      pending_.reset();
      generation = generation_.load();
      cancel_ = false;
    }
    try {
      render_one(request, generation);
    } catch (const std::exception& e) {
      std::lock_guard lock(mutex_);
      if (generation == generation_.load()) error_ = e.what();
    }
  }
}

void RenderSession::render_one(const RenderRequest& request, std::uint64_t generation) {
  validate_render_settings(request.settings);
  if (!prepared_) {
    const Clock::time_point t = Clock::now();
    prepared_ = std::make_unique<PreparedScene>(scene_);
    prepare_seconds_ = seconds_since(t);
    ++prepare_count_;
  }
  prepared_->set_camera(request.camera);
  prepared_->set_materials(request.materials);
  prepared_->set_lights(request.lights);
  const color::ColorSpace film_space = film_color_space(request.settings.transport);

  const Clock::time_point start = Clock::now();
  Clock::time_point last_pass = start;
  int groups = 0, last_next_sample = -1;
  RenderHooks hooks;
  hooks.cancel = &cancel_;
  // A tiny interval makes the renderer hand over the film after every pass.
  hooks.checkpoint_interval_seconds = 1e-9;
  // One published frame: after a pass (whole samples), or in the middle of one with
  // bounces per pass (each pixel's completed samples; spp counts the whole passes).
  const auto publish_film = [&](const Film& film, int next_sample, bool mid_pass) {
    ++groups;
    auto frame = std::make_shared<FilmFrame>();
    frame->generation = generation;
    frame->film = ImageRgbF{film.width(), film.height(), film.mean_rgb()};
    if (film.aovs().normal || film.aovs().depth) {
      AovImages aovs = film_aov_images(film, Mat3::identity());
      if (film.aovs().normal) frame->normals = std::move(aovs.normal);
      frame->coverage = std::move(aovs.depth_coverage);
    }
    frame->film_space = film_space;
    frame->passes = groups;
    frame->spp = next_sample - request.settings.first_sample;
    frame->elapsed_seconds = seconds_since(start);
    frame->last_pass_seconds = std::chrono::duration<double>(Clock::now() - last_pass).count();
    frame->samples_per_second = frame->elapsed_seconds > 0
        ? static_cast<double>(frame->spp) * static_cast<double>(film.pixel_count()) / frame->elapsed_seconds
        : 0.0;
    frame->finished = !mid_pass && next_sample >= request.settings.samples_per_pixel;
    last_pass = Clock::now();
    {
      std::lock_guard lock(mutex_);
      frame->serial = ++serial_;
    }
    publish(std::move(frame));
  };
  hooks.on_checkpoint = [&](const Film& film, int next_sample) {
    // The renderer repeats the last film when it ends; one frame per pass is enough.
    if (generation != generation_.load() || next_sample == last_next_sample) return;
    last_next_sample = next_sample;
    publish_film(film, next_sample, false);
  };
  if (request.settings.bounces_per_pass > 0)
    hooks.on_bounces = [&](const Film& film, int pass_start) {
      if (generation == generation_.load()) publish_film(film, pass_start, true);
    };
  render(*prepared_, request.settings, hooks);
}

}  // namespace prism::viewer
