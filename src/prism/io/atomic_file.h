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

}  // namespace prism
