#include "prism/scene/loaders/gltf_accessors.h"

#include <cmath>
#include <cstring>

#include <fmt/format.h>
#include "prism/scene/loaders/tinygltf_config.h"

#include "prism/core/error.h"

namespace prism::loaders {
namespace {

std::size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

// Component `c` of element `i` as a double; integer components are normalised when the
// accessor says so (glTF 2.0 §3.11).
struct AccessorView {
  const unsigned char* data = nullptr;
  std::size_t count = 0, stride = 0, components = 0;
  int component_type = 0;
  bool normalized = false;

  double get(std::size_t i, std::size_t c) const {
    const unsigned char* p = data + i * stride + c * component_size(component_type);
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
      case TINYGLTF_COMPONENT_TYPE_BYTE: { const auto v = static_cast<std::int8_t>(*p); return normalized ? std::max(v / 127.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return normalized ? v / 65535.0 : v; }
      case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return normalized ? std::max(v / 32767.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
      case TINYGLTF_COMPONENT_TYPE_INT: { std::int32_t v; std::memcpy(&v, p, 4); return v; }
      default: return 0.0;
    }
  }
};

AccessorView view_of(const tinygltf::Model& model, int index, int type, std::initializer_list<int> component_types,
                     const std::string& where) {
  const auto fail = [&](std::string_view what) -> void {
    throw SceneError(fmt::format("{}: accessor {}: {}", where, index, what));
  };
  if (index < 0 || index >= static_cast<int>(model.accessors.size())) fail("does not exist");
  const tinygltf::Accessor& a = model.accessors[index];
  if (a.type != type) fail("has the wrong type");
  bool accepted = false;
  for (int t : component_types) accepted |= a.componentType == t;
  if (!accepted) fail(fmt::format("component type {} is not accepted here", a.componentType));
  if (a.sparse.isSparse) fail("sparse accessors are not supported");
  AccessorView v;
  v.count = a.count;
  v.components = static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
  v.component_type = a.componentType;
  v.normalized = a.normalized;
  if (v.count == 0) return v;
  if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model.bufferViews.size())) fail("has no valid buffer view");
  const tinygltf::BufferView& bv = model.bufferViews[a.bufferView];
  if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model.buffers.size())) fail("its buffer view has no valid buffer");
  const auto& buffer = model.buffers[bv.buffer].data;
  const std::size_t element = v.components * component_size(a.componentType);
  v.stride = bv.byteStride ? bv.byteStride : element;
  if (v.stride < element || v.stride > 252) fail("byte stride is out of range");
  // Checked in 128-bit-safe steps: offset + (count − 1)·stride + element ≤ view length ≤ buffer.
  if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset) fail("its buffer view lies outside the buffer");
  if (a.byteOffset > bv.byteLength) fail("byte offset lies outside the buffer view");
  const std::size_t room = bv.byteLength - a.byteOffset;
  if (room < element || (v.count - 1) > (room - element) / v.stride) fail("its elements run past the buffer view");
  v.data = buffer.data() + bv.byteOffset + a.byteOffset;
  return v;
}

template <typename T, std::size_t N>
std::vector<T> read_floats(const AccessorView& v, int index, const std::string& where) {
  std::vector<T> out(v.count);
  for (std::size_t i = 0; i < v.count; ++i) {
    float x[N];
    for (std::size_t c = 0; c < N; ++c) {
      const double value = v.get(i, c);
      if (!std::isfinite(value)) throw SceneError(fmt::format("{}: accessor {}: element {} is not finite", where, index, i));
      x[c] = static_cast<float>(value);
    }
    if constexpr (N == 2) out[i] = T(x[0], x[1]);
    else out[i] = T(x[0], x[1], x[2]);
  }
  return out;
}

}  // namespace

std::vector<Vec3f> read_gltf_vec3(const tinygltf::Model& model, int accessor, const std::string& where) {
  const auto v = view_of(model, accessor, TINYGLTF_TYPE_VEC3,
                         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                         where);
  return read_floats<Vec3f, 3>(v, accessor, where);
}

std::vector<Vec3f> read_gltf_vec4_xyz(const tinygltf::Model& model, int accessor, const std::string& where) {
  auto v = view_of(model, accessor, TINYGLTF_TYPE_VEC4,
                   {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}, where);
  return read_floats<Vec3f, 3>(v, accessor, where);
}

std::vector<float> read_gltf_tangent_signs(const tinygltf::Model& model, int accessor, const std::string& where) {
  const auto v = view_of(model, accessor, TINYGLTF_TYPE_VEC4,
                         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
                         where);
  std::vector<float> out(v.count);
  for (std::size_t i = 0; i < v.count; ++i) {
    const double w = v.get(i, 3);
    if (!std::isfinite(w)) throw SceneError(fmt::format("{}: accessor {}: element {} is not finite", where, accessor, i));
    out[i] = w < 0.0 ? -1.0f : 1.0f;
  }
  return out;
}

std::vector<Vec2f> read_gltf_vec2(const tinygltf::Model& model, int accessor, const std::string& where) {
  const auto v = view_of(model, accessor, TINYGLTF_TYPE_VEC2,
                         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
                         where);
  return read_floats<Vec2f, 2>(v, accessor, where);
}

std::vector<std::uint32_t> read_gltf_indices(const tinygltf::Model& model, int accessor, const std::string& where) {
  const auto v = view_of(model, accessor, TINYGLTF_TYPE_SCALAR,
                         {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                         where);
  std::vector<std::uint32_t> out(v.count);
  for (std::size_t i = 0; i < v.count; ++i) out[i] = static_cast<std::uint32_t>(v.get(i, 0));
  return out;
}

}  // namespace prism::loaders
