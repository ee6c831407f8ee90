#pragma once
// Writes that never leave a truncated file behind: data goes to a temporary file next to
// the target and is renamed over it only once complete (rename is atomic on POSIX).
#include <filesystem>

namespace prism {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();  // removes the temporary file unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Where to write the data.
  const std::filesystem::path& temporary_path() const { return temporary_; }
  // Moves the finished temporary file onto the target; throws IoError on failure.
  void commit();

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

// Throws IoError when `path` cannot be created: its directory is missing or not
// writable, or the path names a directory. Lets a command fail before a long render.
void check_writable_output(const std::filesystem::path& path);

// Test seam for write faults (a full disk) without a real full disk: once armed, the
// Nth AtomicFile::commit() from then on (1 = the next one) fails with `error` (default
// ENOSPC) as if the data had not fit: it throws the IoError a real failure would, the
// temporary file is removed and the target keeps its previous content. Every file Prism
// writes goes through commit(), so this reaches EXR, PNG, AVIF, checkpoints and camera
// JSON alike. Only tests arm it; it is off unless armed and costs one atomic load.
struct WriteFaults {
  static void fail_nth_commit(int n, int error = 28 /* ENOSPC */);
  static void clear();
  // Commits attempted since the fault was last armed or cleared.
  static int commits_seen();
};

}  // namespace prism
