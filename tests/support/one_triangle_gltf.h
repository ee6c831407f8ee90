#pragma once
// A one-triangle glTF document (positions only, data URI) wearing the given material, for
// tests of a material extension's reading: `extension` is listed in extensionsUsed.
#include <string>

#include "prism/scene/loaders/gltf_scene.h"
#include "prism/scene/scene.h"

namespace prism::test {

inline Scene one_triangle_gltf(const std::string& material, const std::string& extension) {
  const std::string text = R"({"asset": {"version": "2.0"}, "extensionsUsed": [")" + extension + R"("],
    "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA", "byteLength": 36}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "materials": [)" + material + R"(], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
  return loaders::parse_gltf_scene({reinterpret_cast<const unsigned char*>(text.data()), text.size()}, "test.gltf",
                                   {}, {});
}

}  // namespace prism::test
