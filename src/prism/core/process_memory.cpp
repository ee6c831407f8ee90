#include "prism/core/process_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace prism {
namespace {

// The value of a "Key:   1234 kB" line of /proc/self/status, in bytes.
std::optional<std::uint64_t> status_kilobytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key + ":", 0) != 0) continue;
    std::istringstream fields(line.substr(key.size() + 1));
    std::uint64_t kilobytes = 0;
    std::string unit;
    if (!(fields >> kilobytes >> unit) || unit != "kB") return std::nullopt;
    return kilobytes * 1024u;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> peak_resident_set_bytes() { return status_kilobytes("VmHWM"); }

std::optional<std::uint64_t> resident_set_bytes() { return status_kilobytes("VmRSS"); }

}  // namespace prism
