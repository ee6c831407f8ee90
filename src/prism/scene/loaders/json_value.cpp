#include "prism/scene/loaders/json_value.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism::loaders {
namespace {

std::string_view type_name(const nlohmann::json& j) { return j.type_name(); }

}  // namespace

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
  if (!is_object()) fail(fmt::format("expected an object, found {}", type_name(*value_)));
  for (const auto& [key, value] : value_->items()) {
    bool known = false;
    for (const auto k : keys) known = known || k == key;
    if (known) continue;
    const std::string where = path();
    document_->unknown_keys.push_back(where.empty() ? key : where + "." + key);
  }
}

bool JsonValue::has(std::string_view key) const { return is_object() && value_->contains(key); }

std::optional<JsonValue> JsonValue::find(std::string_view key) const {
  if (!is_object()) fail(fmt::format("expected an object, found {}", type_name(*value_)));
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  const std::string where = path();
  return JsonValue(*it, where.empty() ? std::string(key) : where + "." + std::string(key), *document_);
}

JsonValue JsonValue::operator[](std::string_view key) const {
  std::optional<JsonValue> v = find(key);
  if (!v) fail(fmt::format("missing required key '{}'", key));
  return *v;
}

std::size_t JsonValue::size(std::size_t max_size) const {
  if (!is_array()) fail(fmt::format("expected an array, found {}", type_name(*value_)));
  if (value_->size() > max_size) fail(fmt::format("expected at most {} elements, found {}", max_size, value_->size()));
  return value_->size();
}

JsonValue::ElementPaths JsonValue::element_paths(std::size_t max_size) const {
  size(max_size);
  if (array_path_ && inner_ == kNoIndex) return {array_path_, outer_};  // a vertex [x, y, z] of a list of them
  return {&document_->array_paths.emplace_back(path()), kNoIndex};
}

std::vector<JsonValue> JsonValue::elements(std::size_t max_size) const {
  const ElementPaths paths = element_paths(max_size);
  std::vector<JsonValue> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i) out.push_back(element(paths, i));
  return out;
}

double JsonValue::as_double() const {
  if (!is_number()) fail(fmt::format("expected a number, found {}", type_name(*value_)));
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
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
  if (!value_->is_number_integer()) fail(fmt::format("expected an integer, found {}", type_name(*value_)));
  if (value_->is_number_unsigned() && value_->get<std::uint64_t>() > static_cast<std::uint64_t>(max))
    fail(fmt::format("{} is out of range [{}, {}]", value_->get<std::uint64_t>(), min, max));
  const std::int64_t v = value_->get<std::int64_t>();
  if (v < min || v > max) fail(fmt::format("{} is out of range [{}, {}]", v, min, max));
  return v;
}

bool JsonValue::as_bool() const {
  if (!value_->is_boolean()) fail(fmt::format("expected true or false, found {}", type_name(*value_)));
  return value_->get<bool>();
}

std::string JsonValue::as_string() const {
  if (!is_string()) fail(fmt::format("expected a string, found {}", type_name(*value_)));
  return value_->get<std::string>();
}

Vec3f JsonValue::as_vec3() const {
  if (!is_array() || value_->size() != 3) fail("expected an array of 3 numbers");
  const auto e = elements();
  return {e[0].as_float(), e[1].as_float(), e[2].as_float()};
}

Vec2f JsonValue::as_vec2() const {
  if (!is_array() || value_->size() != 2) fail("expected an array of 2 numbers");
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
