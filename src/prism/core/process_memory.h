#pragma once
// This process' own memory figures as the kernel counts them (Linux /proc/self/status).
#include <cstdint>
#include <optional>

namespace prism {

// The peak resident set of this process since it started (was exec'd), in bytes: VmHWM of
// /proc/self/status. Unlike getrusage's ru_maxrss it does not include the peak of the
// process that started this one: at exec Linux folds the old address space's high-water
// mark into ru_maxrss, and a posix_spawn (vfork-style) child's old address space is its
// parent's. Nothing where /proc/self/status has no VmHWM line (not Linux).
std::optional<std::uint64_t> peak_resident_set_bytes();

// The resident set now, in bytes (VmRSS); nothing where it is not reported.
std::optional<std::uint64_t> resident_set_bytes();

}  // namespace prism
