// libFuzzer target: the pbrt-v4 scene parser (tokenizer, parameters, directives, shapes,
// materials, lights). The scene has no folder, so Include, plymesh and image textures are
// refused: only the text itself is exercised.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "prism/core/error.h"
#include "prism/scene/loaders/pbrt_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    prism::loaders::parse_pbrt_scene(text, "fuzz.pbrt", {});
  } catch (const prism::Error&) {
  }
  return 0;
}
