#include "prism/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {
namespace fs = std::filesystem;

namespace {
std::atomic<int> g_fault_at{0};       // 0: no fault armed
std::atomic<int> g_fault_errno{ENOSPC};
std::atomic<int> g_commits{0};
}  // namespace

void WriteFaults::fail_nth_commit(int n, int error) {
  g_commits.store(0);
  g_fault_errno.store(error);
  g_fault_at.store(n > 0 ? n : 0);
}

void WriteFaults::clear() { fail_nth_commit(0); }

int WriteFaults::commits_seen() { return g_commits.load(); }

AtomicFile::AtomicFile(fs::path target) : target_(std::move(target)) {
  static std::atomic<unsigned> counter{0};
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  temporary_ = dir / fmt::format(".{}.tmp-{}-{}", target_.filename().string(), ::getpid(), counter++);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ignored;
    fs::remove(temporary_, ignored);
  }
}

void AtomicFile::commit() {
  if (const int at = g_fault_at.load(std::memory_order_relaxed); at > 0 && g_commits.fetch_add(1) + 1 == at)
    throw IoError(fmt::format("cannot write '{}': {}", target_.string(), std::strerror(g_fault_errno.load())));
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
    throw IoError(fmt::format("cannot write '{}': {}", target_.string(), std::strerror(errno)));
  committed_ = true;
}

void check_writable_output(const fs::path& path) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw IoError(fmt::format("cannot write '{}': directory '{}' does not exist", path.string(), dir.string()));
  if (fs::is_directory(path, ec))
    throw IoError(fmt::format("cannot write '{}': it is a directory", path.string()));
  // Permission bits do not tell the whole story (root, read-only mounts, ACLs): create
  // and remove the temporary file a real write would use.
  AtomicFile probe(path);
  std::FILE* f = std::fopen(probe.temporary_path().c_str(), "wb");
  if (!f) throw IoError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  std::fclose(f);
}

}  // namespace prism
