#include "prism/scene/loaders/json_value.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism::loaders {

std::string JsonValue::path() const {
  if (!array_path_) return path_;
  std::string path = fmt::format("{}[{}]", *array_path_, outer_);
  if (inner_ != kNoIndex) path += fmt::format("[{}]", inner_);
  return path;
}

void JsonValue::fail(std::string_view what) const {
  const std::string where = path();
  throw SceneError(fmt::format("{}: {}: {}", document_->source, where.empty() ? "(top level)" : where, what));
}

void JsonValue::expect_keys(std::initializer_list<std::string_view> keys) const {
  if (!is_object()) fail(fmt::format("expected an object, found {}", json_type_name(type())));
  const std::size_t members = tree_->size(node_);
  JsonTree::Node k = tree_->first_child(node_);
  for (std::size_t i = 0; i < members; ++i, k = tree_->next(k + 1)) {
    const std::string_view key = tree_->string(k);
    bool known = false;
    for (const auto k : keys) known = known || k == key;
    if (known) continue;
    const std::string where = path();
    document_->unknown_keys.push_back(where.empty() ? std::string(key) : where + "." + std::string(key));
  }
}

std::optional<JsonTree::Node> JsonValue::member(std::string_view key) const {
  const std::size_t members = tree_->size(node_);
  JsonTree::Node k = tree_->first_child(node_);
  for (std::size_t i = 0; i < members; ++i, k = tree_->next(k + 1))
    if (tree_->string(k) == key) return k + 1;
  return std::nullopt;
}

bool JsonValue::has(std::string_view key) const { return is_object() && member(key); }

std::optional<JsonValue> JsonValue::find(std::string_view key) const {
  if (!is_object()) fail(fmt::format("expected an object, found {}", json_type_name(type())));
  const std::optional<JsonTree::Node> value = member(key);
  if (!value) return std::nullopt;
  const std::string where = path();
  return JsonValue(*tree_, *value, where.empty() ? std::string(key) : where + "." + std::string(key), *document_);
}

JsonValue JsonValue::operator[](std::string_view key) const {
  std::optional<JsonValue> v = find(key);
  if (!v) fail(fmt::format("missing required key '{}'", key));
  return *v;
}

std::size_t JsonValue::size(std::size_t max_size) const {
  if (!is_array()) fail(fmt::format("expected an array, found {}", json_type_name(type())));
  const std::size_t count = tree_->size(node_);
  if (count > max_size) fail(fmt::format("expected at most {} elements, found {}", max_size, count));
  return count;
}

JsonValue::ElementPaths JsonValue::element_paths(std::size_t max_size) const {
  size(max_size);
  if (array_path_ && inner_ == kNoIndex) return {array_path_, outer_};  // a vertex [x, y, z] of a list of them
  return {&document_->array_paths.emplace_back(path()), kNoIndex};
}

std::vector<JsonValue> JsonValue::elements(std::size_t max_size) const {
  const ElementPaths paths = element_paths(max_size);
  std::vector<JsonValue> out;
  const std::size_t count = tree_->size(node_);
  out.reserve(count);
  JsonTree::Node child = tree_->first_child(node_);
  for (std::size_t i = 0; i < count; ++i, child = tree_->next(child)) out.push_back(element(paths, child, i));
  return out;
}

double JsonValue::as_double() const {
  if (!is_number()) fail(fmt::format("expected a number, found {}", json_type_name(type())));
  return tree_->number(node_);  // always finite: the parser refuses numbers beyond a double
}

float JsonValue::as_float() const {
  const double v = as_double();
  if (std::abs(v) > std::numeric_limits<float>::max()) fail("number out of single-precision range");
  return static_cast<float>(v);
}

float JsonValue::as_float(float min, float max) const {
  const float v = as_float();
  if (!(v >= min && v <= max)) fail(fmt::format("{} is out of range [{}, {}]", v, min, max));
  return v;
}

std::int64_t JsonValue::as_integer(std::int64_t min, std::int64_t max) const {
  if (type() == JsonType::number) {
    // Integers beyond int64 are held as doubles: say what is wrong with them.
    const double d = tree_->number(node_);
    if (d == std::trunc(d) && std::abs(d) >= 0x1p63) fail(fmt::format("{} is out of range [{}, {}]", d, min, max));
  }
  if (type() != JsonType::integer) fail(fmt::format("expected an integer, found {}", json_type_name(type())));
  const std::int64_t v = tree_->integer(node_);
  if (v < min || v > max) fail(fmt::format("{} is out of range [{}, {}]", v, min, max));
  return v;
}

bool JsonValue::as_bool() const {
  if (type() != JsonType::boolean) fail(fmt::format("expected true or false, found {}", json_type_name(type())));
  return tree_->boolean(node_);
}

std::string JsonValue::as_string() const {
  if (!is_string()) fail(fmt::format("expected a string, found {}", json_type_name(type())));
  return std::string(tree_->string(node_));
}

Vec3f JsonValue::as_vec3() const {
  if (!is_array() || tree_->size(node_) != 3) fail("expected an array of 3 numbers");
  const auto e = elements();
  return {e[0].as_float(), e[1].as_float(), e[2].as_float()};
}

Vec2f JsonValue::as_vec2() const {
  if (!is_array() || tree_->size(node_) != 2) fail("expected an array of 2 numbers");
  const auto e = elements();
  return {e[0].as_float(), e[1].as_float()};
}

float JsonValue::get_float(std::string_view key, float fallback) const {
  const auto v = find(key);
  return v ? v->as_float() : fallback;
}

float JsonValue::get_float(std::string_view key, float fallback, float min, float max) const {
  const auto v = find(key);
  return v ? v->as_float(min, max) : fallback;
}

bool JsonValue::get_bool(std::string_view key, bool fallback) const {
  const auto v = find(key);
  return v ? v->as_bool() : fallback;
}

std::string JsonValue::get_string(std::string_view key, std::string fallback) const {
  const auto v = find(key);
  return v ? v->as_string() : fallback;
}

Vec3f JsonValue::get_vec3(std::string_view key, const Vec3f& fallback) const {
  const auto v = find(key);
  return v ? v->as_vec3() : fallback;
}

}  // namespace prism::loaders
