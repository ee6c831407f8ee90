#pragma once
// The viewer's render worker: one thread that runs prism::render in a restartable loop.
// restart() cancels the render in flight (it stops after its current pass) and starts a
// new one with the request's camera, materials, lights and settings (the scene's geometry
// and BVH are prepared once and reused by every restart); the film after every pass is
// published as a FilmFrame the UI and display threads read without waiting.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "prism/color/color_space.h"
#include "prism/io/image.h"
#include "prism/render/prepared_scene.h"
#include "prism/render/renderer.h"
#include "prism/scene/scene.h"

namespace prism::viewer {

// Everything the UI can change that changes the rendered image.
struct RenderRequest {
  Camera camera;
  std::vector<Material> materials;
  std::vector<Light> lights;
  RenderSettings settings;
};

// One published state of the film (means, not sums) and the progress that made it.
struct FilmFrame {
  std::uint64_t generation = 0;  // which restart this belongs to
  std::uint64_t serial = 0;      // increases with every published frame
  ImageRgbF film;                // scene-linear means in film_space
  std::optional<ImageRgbF> normals;  // the normal AOV (world space), when the film keeps it
  // Per pixel, the fraction of samples whose camera ray hit a surface (the depth AOV's
  // coverage, when the film keeps it): what exposure metering counts. Empty otherwise.
  std::vector<float> coverage;
  color::ColorSpace film_space;
  int passes = 0;                // progressive updates (groups of samples_per_pass samples)
  int spp = 0;                   // samples per pixel in the film
  double elapsed_seconds = 0;    // since the restart: time to the current spp
  double last_pass_seconds = 0;
  double samples_per_second = 0;
  bool finished = false;         // the render reached its sample target
};

class RenderSession {
 public:
  explicit RenderSession(Scene scene);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Cancels the current render and starts `request`; returns its generation.
  std::uint64_t restart(const RenderRequest& request);
  std::shared_ptr<const FilmFrame> latest() const;
  std::uint64_t generation() const { return generation_.load(); }
  // The message of the last render that threw (bad settings), if any; cleared on restart.
  std::optional<std::string> error() const;
  // How often the scene was prepared (flattened, BVH built): once per session, however
  // many restarts; and how long that took.
  int prepare_count() const { return prepare_count_.load(); }
  double prepare_seconds() const { return prepare_seconds_.load(); }

 private:
  void run();
  void render_one(const RenderRequest& request, std::uint64_t generation);
  void publish(std::shared_ptr<const FilmFrame> frame);

  Scene scene_;  // as loaded; prepared once by the worker
  // Flattened scene and BVH, built by the worker's first render and kept across restarts
  // (restarts change camera, materials, lights and settings, never geometry).
  std::unique_ptr<PreparedScene> prepared_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<RenderRequest> pending_;
  std::shared_ptr<const FilmFrame> latest_;
  std::optional<std::string> error_;
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<bool> cancel_{false};
  std::atomic<int> prepare_count_{0};
  std::atomic<double> prepare_seconds_{0.0};
  bool quit_ = false;
  std::uint64_t serial_ = 0;
  std::thread worker_;
};

}  // namespace prism::viewer
