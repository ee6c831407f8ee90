#include "prism/core/parallel.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>

// ThreadSanitizer and an uninstrumented oneTBB (the distribution's libtbb): TBB hands tasks
// to its workers and joins them through atomics inside libtbb, which TSan cannot see, so
// without help every parallel_for reports the caller's writes before the loop and the
// workers' writes after it as races. Telling TSan about the fork (release before, acquire
// in each chunk) and the join (release after each chunk, acquire after the loop) restores
// exactly the ordering TBB guarantees; races between chunks are still reported.
#if defined(__SANITIZE_THREAD__)
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#define PRISM_TSAN_ACQUIRE(addr) __tsan_acquire(addr)
#define PRISM_TSAN_RELEASE(addr) __tsan_release(addr)
#else
#define PRISM_TSAN_ACQUIRE(addr) static_cast<void>(addr)
#define PRISM_TSAN_RELEASE(addr) static_cast<void>(addr)
#endif

namespace prism {

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(int threads) : impl_(std::make_unique<Impl>()) {
  if (threads > 0)
    impl_->control = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
}

ThreadLimit::~ThreadLimit() = default;

int ThreadLimit::hardware_threads() { return tbb::info::default_concurrency(); }

void parallel_for(std::size_t count, std::size_t grain,
                  const std::function<void(std::size_t, std::size_t)>& body) {
  char fork = 0, join = 0;  // addresses only: TSan's synchronisation objects
  PRISM_TSAN_RELEASE(&fork);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      PRISM_TSAN_ACQUIRE(&fork);
                      body(r.begin(), r.end());
                      PRISM_TSAN_RELEASE(&join);
                    },
                    tbb::simple_partitioner());
  PRISM_TSAN_ACQUIRE(&join);
}

}  // namespace prism
