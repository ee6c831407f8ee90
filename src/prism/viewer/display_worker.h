#pragma once
// The viewer's display thread: runs the display pipeline (or a debug view) of
// prism::display on the latest film with the latest display controls and hands the UI an
// 8-bit RGBA image to show. Display-only changes re-run this, never the renderer.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "prism/display/display_pipeline.h"
#include "prism/io/hdr10_metadata.h"
#include "prism/viewer/render_session.h"
#include "prism/viewer/viewer_state.h"

namespace prism::viewer {

struct DisplayJob {
  std::shared_ptr<const FilmFrame> film;
  DisplayControls controls;
  std::uint64_t controls_version = 0;
  // Auto exposure: the EV100 the previous frame showed (none: this is the first, which
  // shows the metered EV at once) and the seconds since, for the eye adaptation.
  std::optional<double> shown_ev100;
  double seconds_since_shown = 0;
};

struct DisplayFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;      // 8-bit code values, what the window shows
  std::uint64_t film_serial = 0;
  std::uint64_t controls_version = 0;
  double display_seconds = 0;          // time the pipeline took
  // The pipeline's own output (no debug view), for saving and the HDR10 panel.
  std::shared_ptr<const display::DisplayImage> image;
  ContentLightLevel content_light;     // measured on `image`
  double ev100 = 0;                    // the exposure shown (auto: adapted toward metered_ev100)
  std::optional<double> metered_ev100; // auto exposure: what the meter read on this film
  bool exposure_adapting = false;      // the shown EV has not reached the metered one yet
  // An HDR target in this SDR window: what is shown is the same rendering's SDR 100-nit
  // target (never PQ code values); `image` stays the HDR output that saving writes.
  std::string preview_note;
  std::string error;                   // a view or setting the film cannot show
};

class DisplayWorker {
 public:
  DisplayWorker();
  ~DisplayWorker();
  DisplayWorker(const DisplayWorker&) = delete;
  DisplayWorker& operator=(const DisplayWorker&) = delete;

  // Queues a job; a job not yet started is replaced (only the newest matters).
  void submit(DisplayJob job);
  std::shared_ptr<const DisplayFrame> latest() const;
  bool busy() const;

 private:
  void run();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<DisplayJob> pending_;
  std::shared_ptr<const DisplayFrame> latest_;
  std::optional<std::chrono::steady_clock::time_point> latest_time_;  // when latest_ was made
  bool working_ = false, quit_ = false;
  std::thread worker_;
};

// The job's image, computed on the calling thread (the worker's body; also for tests).
DisplayFrame compute_display_frame(const DisplayJob& job);

}  // namespace prism::viewer
