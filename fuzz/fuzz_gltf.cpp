// libFuzzer target: glTF 2.0 and GLB (tinygltf's parser, Prism's accessor reads, materials,
// node hierarchy). No folder: external uris are refused, so only the input is read. A file
// with material variants is parsed again wearing its last one (KHR_materials_variants).
#include <cstddef>
#include <cstdint>

#include "prism/core/error.h"
#include "prism/scene/loaders/gltf_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const prism::Scene scene = prism::loaders::parse_gltf_scene({data, size}, "fuzz.gltf", {});
    if (!scene.material_variants.empty())
      prism::loaders::parse_gltf_scene({data, size}, "fuzz.gltf", {},
                                       prism::LoadOptions{.material_variant = scene.material_variants.back()});
  } catch (const prism::Error&) {
  }
  return 0;
}
