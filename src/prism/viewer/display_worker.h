#pragma once
// The viewer's display thread: runs the display pipeline (or a debug view) of
// prism::display on the latest film with the latest display controls and hands the UI an
// 8-bit RGBA image to show. Display-only changes re-run this, never the renderer.
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
  // HDR outputs only: the UI as drawn (straight-alpha 8-bit sRGB RGBA at the output size),
  // composited as an SDR overlay by display/ui_overlay.h.
  std::shared_ptr<const EncodedImage> ui_rgba;
};

struct DisplayFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;      // 8-bit code values, what the window shows
  std::uint64_t film_serial = 0;
  std::uint64_t controls_version = 0;
  bool ui_composited = false;          // the UI is already in the image (HDR path)
  double display_seconds = 0;          // time the pipeline took
  // The pipeline's own output (no debug view), for saving and the HDR10 panel.
  std::shared_ptr<const display::DisplayImage> image;
  ContentLightLevel content_light;     // measured on `image`
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
  bool working_ = false, quit_ = false;
  std::thread worker_;
};

// The job's image, computed on the calling thread (the worker's body; also for tests).
DisplayFrame compute_display_frame(const DisplayJob& job);

}  // namespace prism::viewer
