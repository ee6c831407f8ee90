#pragma once
// A JSON text (RFC 8259) parsed into one flat array of nodes in document order: a container
// is followed by its descendants and knows where they end, so its elements are read by
// stepping from one sibling to the next, and a million-number mesh array is one block of
// 16-byte nodes written once, never moved. Strings without escapes are views into the text;
// those with escapes are decoded into the tree. This replaced nlohmann::json for scene
// files, whose per-character token buffer and strtod made up 85 % of a 1 M-triangle JSON
// scene's load (docs/performance-design.md "JSON scene reader").
//
// Stricter than RFC 8259 where it leaves choices to the reader: duplicate keys in one object,
// ill-formed UTF-8 (RFC 3629), unpaired surrogate escapes and numbers beyond a double are
// errors. A UTF-8 byte order mark before the value is skipped.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

enum class JsonType : std::uint8_t { null, boolean, integer, number, string, array, object };

// "null", "boolean", "number" (integers too), "string", "array" or "object".
std::string_view json_type_name(JsonType type);

// What is wrong and the byte offset in the text where it is.
class JsonSyntaxError : public std::runtime_error {
 public:
  JsonSyntaxError(std::size_t offset, const std::string& reason) : std::runtime_error(reason), offset_(offset) {}
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

class JsonTree {
 public:
  using Node = std::uint32_t;  // index of a node; the text is limited to 4 GiB

  // Parses the whole text (one value, whitespace around it); throws JsonSyntaxError. The
  // tree refers to the text, which must outlive it.
  explicit JsonTree(std::string_view text);

  Node root() const { return 0; }
  JsonType type(Node n) const { return nodes_[n].type; }
  // Elements of an array, members of an object; 0 for anything else.
  std::size_t size(Node n) const { return is_container(n) ? nodes_[n].count : 0; }
  // The first element of a non-empty array, or the key of a non-empty object's first member
  // (its value is the node after it).
  Node first_child(Node n) const { return n + 1; }
  // The node after `n` and all of its descendants: the next element, key or member value.
  Node next(Node n) const { return is_container(n) ? static_cast<Node>(nodes_[n].payload) : n + 1; }

  bool boolean(Node n) const { return nodes_[n].payload != 0; }
  std::int64_t integer(Node n) const { return static_cast<std::int64_t>(nodes_[n].payload); }
  // A number or an integer, as a double (always finite).
  double number(Node n) const;
  std::string_view string(Node n) const {
    const Entry& e = nodes_[n];
    return {e.decoded ? decoded_.data() + (e.payload >> 32) : text_.data() + (e.payload & 0xFFFF'FFFF), e.count};
  }
  // The byte offset in the text of a string's opening quote.
  std::size_t string_offset(Node n) const { return (nodes_[n].payload & 0xFFFF'FFFF) - 1; }

 private:
  // 16 bytes. `count`: elements, members, or a string's length in bytes. `payload`: a
  // container's end (see next); a string's offset in text_ (low 32 bits) and, when it had
  // escapes (`decoded`), its offset in decoded_ (high 32 bits); an integer's two's
  // complement; a number's IEEE 754 bits; a boolean.
  struct Entry {
    JsonType type;
    bool decoded;
    std::uint32_t count;
    std::uint64_t payload;
  };
  friend class JsonParser;
  bool is_container(Node n) const { return nodes_[n].type >= JsonType::array; }

  std::string_view text_;
  std::string decoded_;  // the strings with escapes, decoded (UTF-8)
  std::vector<Entry> nodes_;
};

}  // namespace prism
