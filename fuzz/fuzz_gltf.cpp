// libFuzzer target: glTF 2.0 and GLB (tinygltf's parser, Prism's accessor reads, materials,
// node hierarchy). No folder: external uris are refused, so only the input is read.
#include <cstddef>
#include <cstdint>

#include "prism/core/error.h"
#include "prism/scene/loaders/gltf_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    prism::loaders::parse_gltf_scene({data, size}, "fuzz.gltf", {});
  } catch (const prism::Error&) {
  }
  return 0;
}
