#pragma once
// UI frame-time statistics: a rolling window for the overlay and totals for the log.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <vector>

#include "prism/viewer/panels.h"

namespace prism::viewer {

class FrameStats {
 public:
  // Call once per UI frame; returns the frame's duration in seconds.
  double tick() {
    const auto now = std::chrono::steady_clock::now();
    const double dt = started_ ? std::chrono::duration<double>(now - last_).count() : 0.0;
    last_ = now;
    if (started_) {
      recent_[count_ % recent_.size()] = dt;
      ++count_;
      all_.push_back(dt);
    }
    started_ = true;
    return dt;
  }

  UiTimings recent() const {
    UiTimings t;
    const std::size_t n = std::min(count_, recent_.size());
    if (n == 0) return t;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      sum += recent_[i];
      t.frame_ms_max = std::max(t.frame_ms_max, recent_[i] * 1e3);
    }
    t.frame_ms_mean = sum / n * 1e3;
    t.fps = t.frame_ms_mean > 0 ? 1e3 / t.frame_ms_mean : 0;
    return t;
  }

  // Time the UI thread spent on a frame (not waiting for events), seconds.
  void add_work(double seconds) { work_.push_back(seconds); }
  double work_mean_ms() const {
    double sum = 0;
    for (double v : work_) sum += v;
    return work_.empty() ? 0 : sum / work_.size() * 1e3;
  }

  // Percentile (0..100) of all frame times so far, milliseconds.
  double percentile_ms(double p) const {
    if (all_.empty()) return 0;
    std::vector<double> sorted = all_;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t i = std::min(sorted.size() - 1, static_cast<std::size_t>(p / 100.0 * sorted.size()));
    return sorted[i] * 1e3;
  }
  double mean_ms() const {
    double sum = 0;
    for (double v : all_) sum += v;
    return all_.empty() ? 0 : sum / all_.size() * 1e3;
  }
  std::size_t frames() const { return all_.size(); }

 private:
  std::array<double, 60> recent_{};
  std::vector<double> all_, work_;
  std::size_t count_ = 0;
  std::chrono::steady_clock::time_point last_;
  bool started_ = false;
};

}  // namespace prism::viewer
