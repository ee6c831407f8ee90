#pragma once
// The viewer process' memory for the stats overlay and the exit log: the resident set now
// and its peak (core/process_memory.h), read from /proc at most once a second, since the
// overlay asks every UI frame.
#include <chrono>
#include <cstdint>
#include <optional>

#include "prism/core/process_memory.h"

namespace prism::viewer {

struct MemoryFigures {
  double resident_mib = 0, peak_mib = 0;  // 0 where the kernel reports nothing
};

class MemoryMonitor {
 public:
  const MemoryFigures& figures() {
    const auto now = std::chrono::steady_clock::now();
    if (!read_once_ || now - read_at_ >= std::chrono::seconds(1)) {
      figures_ = {mib(resident_set_bytes()), mib(peak_resident_set_bytes())};
      read_at_ = now;
      read_once_ = true;
    }
    return figures_;
  }

 private:
  static double mib(std::optional<std::uint64_t> bytes) {
    return bytes ? static_cast<double>(*bytes) / double(std::uint64_t{1} << 20) : 0.0;
  }
  MemoryFigures figures_;
  std::chrono::steady_clock::time_point read_at_;
  bool read_once_ = false;
};

}  // namespace prism::viewer
