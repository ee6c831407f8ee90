#pragma once
// Checkpoint files: the complete film state of an unfinished render (sums, squared sums,
// counts), the next sample index and the image fingerprint, so that `prism render
// --resume` continues to a result bitwise identical to an uninterrupted render.
//
// Layout (little-endian), version 2: "PRISMCKP", u32 version, u64 fingerprint, i32 width,
// i32 height, i32 first_sample, i32 next_sample, u32 AOV bits (AovSet::bits), then
// width·height × (3 f64 sums, 3 f64 squared sums, u32 count, and for each AOV present:
// albedo 3 f64 sums; normal 3 f64 sums; depth f64 sum, u32 hits), then the u64 FNV-1a hash
// of everything before it. Version 1 (no AOV bits or sums) is refused with a message
// naming the version: its renders can be finished only by the Prism that wrote them.
#include <cstdint>
#include <filesystem>

#include "prism/render/film.h"

namespace prism {

struct Checkpoint {
  std::uint64_t fingerprint = 0;
  int first_sample = 0;
  int next_sample = 0;
  Film film;
};

// Written atomically (temporary file + rename): an interruption never corrupts the
// previous checkpoint. Throws IoError.
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);

// Throws IoError for missing, truncated, corrupt or foreign files.
Checkpoint read_checkpoint(const std::filesystem::path& path);

}  // namespace prism
