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

namespace {

// The body TBB copies into each task. TBB writes a task's range and then copies the body
// into it on the thread that splits the work (oneTBB's start_for declares my_range before
// my_body), after the fork edge below: the copy constructor releases on the copy's
// address and the call acquires on it, so the worker's reads of the range and of these
// members are ordered after the splitting thread's writes too.
struct ChunkBody {
  const std::function<void(std::size_t, std::size_t)>* body;
  char* fork;
  char* join;
  ChunkBody(const std::function<void(std::size_t, std::size_t)>* body_, char* fork_, char* join_)
      : body(body_), fork(fork_), join(join_) {}
  ChunkBody(const ChunkBody& other) : body(other.body), fork(other.fork), join(other.join) {
    PRISM_TSAN_RELEASE(this);
  }
  ChunkBody& operator=(const ChunkBody&) = delete;
  void operator()(const tbb::blocked_range<std::size_t>& r) const {
    PRISM_TSAN_ACQUIRE(const_cast<ChunkBody*>(this));
    PRISM_TSAN_ACQUIRE(fork);
    (*body)(r.begin(), r.end());
    PRISM_TSAN_RELEASE(join);
  }
};

}  // namespace

void parallel_for(std::size_t count, std::size_t grain,
                  const std::function<void(std::size_t, std::size_t)>& body) {
  char fork = 0, join = 0;  // addresses only: TSan's synchronisation objects
  const ChunkBody chunk(&body, &fork, &join);
  PRISM_TSAN_RELEASE(&fork);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain), chunk, tbb::simple_partitioner());
  PRISM_TSAN_ACQUIRE(&join);
}

}  // namespace prism
