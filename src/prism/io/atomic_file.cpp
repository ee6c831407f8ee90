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
