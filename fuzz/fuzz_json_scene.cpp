// libFuzzer target: the prism-scene/1 JSON parser and scene reader. Any exception other
// than prism::Error, any sanitizer report, crash or hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "prism/core/error.h"
#include "prism/scene/loaders/json_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // No scene folder: file references are refused, so the target never touches files.
    prism::loaders::parse_json_scene(text, "fuzz.json", {}, "fuzz");
  } catch (const prism::Error&) {
  }
  return 0;
}
