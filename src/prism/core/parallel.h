#pragma once
// Parallel helpers on oneTBB. Work is split into fixed chunks whose results never depend
// on scheduling, so callers stay deterministic as long as each index writes its own data.
#include <cstddef>
#include <functional>
#include <memory>

namespace prism {

// Limits oneTBB to `threads` worker threads for the lifetime of the object (0 = all cores).
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;
  static int hardware_threads();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Calls body(begin, end) on disjoint sub-ranges of [0, count), each at most `grain` long.
void parallel_for(std::size_t count, std::size_t grain,
                  const std::function<void(std::size_t, std::size_t)>& body);

}  // namespace prism
