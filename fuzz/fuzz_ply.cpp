// libFuzzer target: the PLY mesh reader (ASCII and binary headers, element data, lists).
#include <cstddef>
#include <cstdint>

#include "prism/core/error.h"
#include "prism/scene/loaders/ply_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    prism::loaders::parse_ply_mesh({data, size}, "fuzz.ply");
  } catch (const prism::Error&) {
  }
  return 0;
}
