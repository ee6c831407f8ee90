#include "prism/core/memory_budget.h"

#include <algorithm>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {

std::string format_bytes(std::uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 4) {
    v /= 1024.0;
    ++u;
  }
  if (u == 0) return fmt::format("{} B", bytes);
  return fmt::format("{:.{}f} {}", v, v < 10.0 ? 2 : v < 100.0 ? 1 : 0, units[u]);
}

void MemoryBudget::reserve(std::uint64_t bytes, std::uint64_t transient_bytes, std::string_view what) {
  std::uint64_t used = used_.load();
  for (;;) {
    // used + bytes + transient_bytes > limit_, without overflowing.
    const bool too_much = bytes > limit_ || transient_bytes > limit_ - bytes || used > limit_ - bytes - transient_bytes;
    if (limit_ > 0 && too_much) {
      throw Error(fmt::format("{} needs {} (scene data loaded so far: {}), more than the memory limit of {}", what,
                              format_bytes(std::max(bytes, bytes + transient_bytes)), format_bytes(used),
                              format_bytes(limit_)));
    }
    if (used_.compare_exchange_weak(used, used + bytes)) return;
  }
}

}  // namespace prism
