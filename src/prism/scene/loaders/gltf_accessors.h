#pragma once
// Bounds-checked reads of glTF accessors: every offset, stride and count is checked
// against its buffer view and buffer before a byte is read.
#include <cstdint>
#include <string>
#include <vector>

#include "prism/core/vec.h"

namespace tinygltf {
class Model;
}

namespace prism::loaders {

// Each reader throws SceneError "<where>: accessor N: ..." for a bad reference, a type
// or component type it does not accept, an out-of-range view, or non-finite values.
std::vector<Vec3f> read_gltf_vec3(const tinygltf::Model& model, int accessor, const std::string& where);
std::vector<Vec3f> read_gltf_vec4_xyz(const tinygltf::Model& model, int accessor, const std::string& where);
// The sign of each TANGENT's w (the bitangent's handedness), as ±1.
std::vector<float> read_gltf_tangent_signs(const tinygltf::Model& model, int accessor, const std::string& where);
std::vector<Vec2f> read_gltf_vec2(const tinygltf::Model& model, int accessor, const std::string& where);
std::vector<std::uint32_t> read_gltf_indices(const tinygltf::Model& model, int accessor, const std::string& where);

}  // namespace prism::loaders
