// libFuzzer target: OBJ + MTL (tinyobjloader and Prism's conversion). The input is the OBJ
// text, optionally followed by a line "#MTL" and the text every `mtllib` then reads.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "prism/core/error.h"
#include "prism/scene/loaders/obj_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSeparator = "\n#MTL\n";
  const std::size_t split = input.find(kSeparator);
  const std::string_view obj = input.substr(0, split);
  const std::string mtl = split == std::string_view::npos ? std::string() : std::string(input.substr(split + kSeparator.size()));
  prism::loaders::ObjContext context;  // no folder, no textures: nothing but memory
  context.mtl_text = &mtl;
  prism::Scene scene;
  try {
    prism::loaders::append_obj(scene, obj, "fuzz.obj", context);
    if (!scene.meshes.empty()) prism::validate_scene(scene);
  } catch (const prism::Error&) {
  }
  return 0;
}
