#pragma once
// A read-only view of a parsed JSON value that knows its path in the document
// (`materials[2].roughness`), so every schema error can name where it is, and that collects
// keys the reader did not expect (reported once as a warning).
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "prism/core/vec.h"

namespace prism::loaders {

struct JsonDocument {
  std::string source;                     // file name (or built-in scene name) for messages
  std::vector<std::string> unknown_keys;  // JSON paths of keys no reader asked for
};

class JsonValue {
 public:
  JsonValue(const nlohmann::json& value, std::string path, JsonDocument& document)
      : value_(&value), path_(std::move(path)), document_(&document) {}

  const std::string& path() const { return path_; }
  const nlohmann::json& raw() const { return *value_; }
  bool is_string() const { return value_->is_string(); }
  bool is_object() const { return value_->is_object(); }
  bool is_array() const { return value_->is_array(); }
  bool is_number() const { return value_->is_number(); }

  // Throws SceneError "<source>: <path>: <what>".
  [[noreturn]] void fail(std::string_view what) const;

  // Object access. `expect_keys` requires an object and records any other key as unknown.
  void expect_keys(std::initializer_list<std::string_view> keys) const;
  bool has(std::string_view key) const;
  JsonValue operator[](std::string_view key) const;  // required member
  std::optional<JsonValue> find(std::string_view key) const;

  // Array access: requires an array (of at most `max_size` elements, when given).
  std::vector<JsonValue> elements(std::size_t max_size = SIZE_MAX) const;

  double as_double() const;  // a finite number
  float as_float() const;    // a number that is finite in single precision
  float as_float(float min, float max) const;
  std::int64_t as_integer(std::int64_t min, std::int64_t max) const;
  bool as_bool() const;
  std::string as_string() const;
  Vec3f as_vec3() const;  // [x, y, z]
  Vec2f as_vec2() const;  // [x, y]

  // One of the listed names; the error lists them.
  template <typename Enum>
  Enum as_enum(std::initializer_list<std::pair<std::string_view, Enum>> names) const {
    const std::string s = as_string();
    for (const auto& [name, value] : names)
      if (name == s) return value;
    std::string list;
    for (const auto& [name, value] : names) list += (list.empty() ? "" : ", ") + std::string(name);
    fail("unknown value '" + s + "' (expected one of: " + list + ")");
  }

  // Optional members with defaults.
  float get_float(std::string_view key, float fallback) const;
  float get_float(std::string_view key, float fallback, float min, float max) const;
  bool get_bool(std::string_view key, bool fallback) const;
  std::string get_string(std::string_view key, std::string fallback) const;
  Vec3f get_vec3(std::string_view key, const Vec3f& fallback) const;

 private:
  const nlohmann::json* value_;
  std::string path_;
  JsonDocument* document_;
};

}  // namespace prism::loaders
