#pragma once
// What every scene loader may and may not do with the files a scene refers to.
#include <string>

#include "prism/core/memory_budget.h"

namespace prism {

struct LoadOptions {
  // Scene files may only refer to files inside their own folder (or below it). A
  // reference that escapes it (`../../etc/passwd`, an absolute path, a symbolic link
  // leading out) is refused unless this is set (`--allow-external-paths`).
  bool allow_external_paths = false;
  // Images wider or taller than this many pixels are refused before any pixel memory is
  // allocated.
  int max_texture_dimension = 32768;
  // When set, loaders account for texture texels (before decoding) and mesh arrays in it
  // and refuse what would exceed its limit (--memory-limit). Not owned.
  MemoryBudget* memory_budget = nullptr;
  // glTF KHR_materials_variants: the variant whose materials the primitives take, by name
  // (--variant); empty: each primitive's own material, the file's default look. A name the
  // scene does not define is a UsageError.
  std::string material_variant{};
};

}  // namespace prism
