#pragma once
// A running account of the memory a scene's loaders allocate, checked against
// --memory-limit before each large allocation, so that a scene whose textures or meshes
// cannot fit is refused with a clear message instead of being killed by the OOM killer
// (issue 9). Compressed images are the reason it must happen while reading: a 100 kB PNG
// may declare 30000 × 30000 pixels, 14 GB as float texels.
#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>

namespace prism {

// "1.50 GiB", "12.0 MiB", "512 B".
std::string format_bytes(std::uint64_t bytes);

class MemoryBudget {
 public:
  // limit_bytes 0: unlimited (nothing is ever refused, use is still counted).
  explicit MemoryBudget(std::uint64_t limit_bytes) : limit_(limit_bytes) {}

  // Accounts for `bytes` that stay allocated, after checking that they, plus
  // `transient_bytes` needed only while decoding, fit next to what is already used.
  // Throws Error (exit 1) naming `what`, the sizes and the limit otherwise; nothing is
  // recorded then. Safe to call from several threads.
  void reserve(std::uint64_t bytes, std::uint64_t transient_bytes, std::string_view what);

  std::uint64_t used_bytes() const { return used_.load(); }
  std::uint64_t limit_bytes() const { return limit_; }

 private:
  std::uint64_t limit_;
  std::atomic<std::uint64_t> used_{0};
};

}  // namespace prism
