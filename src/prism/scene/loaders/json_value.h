#pragma once
// A read-only view of a parsed JSON value that knows its path in the document
// (`materials[2].roughness`), so every schema error can name where it is, and that collects
// keys the reader did not expect (reported once as a warning).
#include <array>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "prism/core/vec.h"
#include "prism/scene/loaders/json_tree.h"
#include "prism/scene/type_names.h"

namespace prism::loaders {

struct JsonDocument {
  std::string source;                     // file name (or built-in scene name) for messages
  std::vector<std::string> unknown_keys;  // JSON paths of keys no reader asked for
  // The paths of arrays whose elements were taken, which the elements refer to (a deque:
  // its strings stay where they are as it grows).
  std::deque<std::string> array_paths;
};

class JsonValue {
 public:
  // The tree's root (path "").
  JsonValue(const JsonTree& tree, JsonDocument& document) : tree_(&tree), node_(tree.root()), document_(&document) {}

  // Built when asked for (an error, a message): an array element keeps its array's path and
  // its index, not a formatted string of its own, since a mesh's arrays have millions.
  std::string path() const;
  JsonType type() const { return tree_->type(node_); }
  bool is_string() const { return type() == JsonType::string; }
  bool is_object() const { return type() == JsonType::object; }
  bool is_array() const { return type() == JsonType::array; }
  bool is_number() const { return type() == JsonType::integer || type() == JsonType::number; }
  // A non-empty array whose first element is an array ([[x, y, z], ...]).
  bool is_array_of_arrays() const {
    return is_array() && tree_->size(node_) > 0 && tree_->type(tree_->first_child(node_)) == JsonType::array;
  }

  // Throws SceneError "<source>: <path>: <what>".
  [[noreturn]] void fail(std::string_view what) const;

  // Object access. `expect_keys` requires an object and records any other key as unknown.
  void expect_keys(std::initializer_list<std::string_view> keys) const;
  bool has(std::string_view key) const;
  JsonValue operator[](std::string_view key) const;  // required member
  std::optional<JsonValue> find(std::string_view key) const;

  // Array access: requires an array (of at most `max_size` elements, when given).
  std::vector<JsonValue> elements(std::size_t max_size = SIZE_MAX) const;
  std::size_t size(std::size_t max_size = SIZE_MAX) const;  // the same checks, the element count
  // The elements one at a time, visit(const JsonValue&) in order: for arrays too long to
  // hold a JsonValue per element (a mesh's numbers).
  template <class Visit>
  void for_each_element(Visit&& visit, std::size_t max_size = SIZE_MAX) const {
    const ElementPaths paths = element_paths(max_size);
    const std::size_t count = tree_->size(node_);
    JsonTree::Node child = tree_->first_child(node_);
    for (std::size_t i = 0; i < count; ++i, child = tree_->next(child)) visit(element(paths, child, i));
  }

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
  // The same from a scene enum's name table (scene/type_names.h).
  template <class Enum, std::size_t N>
  Enum as_enum(const std::array<EnumName<Enum>, N>& names) const {
    const std::string s = as_string();
    if (const std::optional<Enum> value = enum_value(names, s)) return *value;
    std::string list;
    for (const EnumName<Enum>& e : names) list += (list.empty() ? "" : ", ") + std::string(e.name);
    fail("unknown value '" + s + "' (expected one of: " + list + ")");
  }

  // Optional members with defaults.
  float get_float(std::string_view key, float fallback) const;
  float get_float(std::string_view key, float fallback, float min, float max) const;
  bool get_bool(std::string_view key, bool fallback) const;
  std::string get_string(std::string_view key, std::string fallback) const;
  Vec3f get_vec3(std::string_view key, const Vec3f& fallback) const;

 private:
  static constexpr std::size_t kNoIndex = SIZE_MAX;
  // Where this array's elements take their paths from: an element of an element keeps its
  // array's path and both indices; any other array's path is stored once in the document.
  struct ElementPaths {
    const std::string* array_path;
    std::size_t outer;  // kNoIndex: the elements' own index is the outer one
  };
  ElementPaths element_paths(std::size_t max_size) const;  // checks the array and its size
  std::optional<JsonTree::Node> member(std::string_view key) const;  // the value of an object's member
  // Element i, at node `child`.
  JsonValue element(const ElementPaths& paths, JsonTree::Node child, std::size_t i) const {
    return paths.outer == kNoIndex ? JsonValue(*tree_, child, paths.array_path, i, kNoIndex, *document_)
                                   : JsonValue(*tree_, child, paths.array_path, paths.outer, i, *document_);
  }
  // An object's member.
  JsonValue(const JsonTree& tree, JsonTree::Node node, std::string path, JsonDocument& document)
      : tree_(&tree), node_(node), path_(std::move(path)), document_(&document) {}
  // Element `outer` of the array at *array_path, or element `inner` of that element.
  JsonValue(const JsonTree& tree, JsonTree::Node node, const std::string* array_path, std::size_t outer,
            std::size_t inner, JsonDocument& document)
      : tree_(&tree), node_(node), array_path_(array_path), outer_(outer), inner_(inner), document_(&document) {}

  const JsonTree* tree_;
  JsonTree::Node node_;
  std::string path_;                        // roots and object members: the whole path
  const std::string* array_path_ = nullptr;  // array elements: their array's path (in the document)
  std::size_t outer_ = kNoIndex, inner_ = kNoIndex;
  JsonDocument* document_;
};

}  // namespace prism::loaders
