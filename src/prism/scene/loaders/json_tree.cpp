#include "prism/scene/loaders/json_tree.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

namespace prism {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_whitespace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }  // RFC 8259 §2

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The code point as UTF-8 at out; returns the byte count (RFC 3629 §3).
std::size_t encode_utf8(std::uint32_t cp, char* out) {
  if (cp < 0x80) {
    out[0] = static_cast<char>(cp);
    return 1;
  }
  if (cp < 0x800) {
    out[0] = static_cast<char>(0xC0 | (cp >> 6));
    out[1] = static_cast<char>(0x80 | (cp & 0x3F));
    return 2;
  }
  if (cp < 0x10000) {
    out[0] = static_cast<char>(0xE0 | (cp >> 12));
    out[1] = static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out[2] = static_cast<char>(0x80 | (cp & 0x3F));
    return 3;
  }
  out[0] = static_cast<char>(0xF0 | (cp >> 18));
  out[1] = static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
  out[2] = static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
  out[3] = static_cast<char>(0x80 | (cp & 0x3F));
  return 4;
}

// The length of the well-formed UTF-8 sequence starting at s[0] (a byte ≥ 0x80), or 0 when it
// is ill-formed: the table of well-formed byte sequences in Unicode 15.0 §3.9, Table 3-7
// (no overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8_sequence_length(const unsigned char* s, std::size_t available) {
  const unsigned char b0 = s[0];
  std::size_t length;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    length = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    length = 3;
    if (b0 == 0xE0) low = 0xA0;
    if (b0 == 0xED) high = 0x9F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    length = 4;
    if (b0 == 0xF0) low = 0x90;
    if (b0 == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (available < length || s[1] < low || s[1] > high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (s[i] < 0x80 || s[i] > 0xBF) return 0;
  return length;
}

// Whether a number token (grammar already checked) is of magnitude ≥ 1, i.e. the decimal
// exponent of its first non-zero digit, 'e' part included, is ≥ 0. Used only to tell overflow
// from underflow when std::from_chars reports a result out of range, which it does only
// when the nearest double is ±inf or 0.
bool magnitude_at_least_one(std::string_view token) {
  constexpr long long kNone = std::numeric_limits<long long>::min();
  long long leading = kNone;  // decimal exponent of the first non-zero digit, before the 'e' part
  std::size_t i = token[0] == '-' ? 1 : 0;
  const std::size_t integer_begin = i;
  while (i < token.size() && is_digit(token[i])) ++i;
  for (std::size_t k = integer_begin; k < i && leading == kNone; ++k)
    if (token[k] != '0') leading = static_cast<long long>(i - 1 - k);
  if (i < token.size() && token[i] == '.') {
    ++i;
    for (long long place = -1; i < token.size() && is_digit(token[i]); ++i, --place)
      if (leading == kNone && token[i] != '0') leading = place;
  }
  if (leading == kNone) return false;  // zero
  long long exponent = 0;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    const bool negative = token[i] == '-';
    if (token[i] == '-' || token[i] == '+') ++i;
    for (; i < token.size(); ++i) exponent = std::min(exponent * 10 + (token[i] - '0'), 1'000'000'000'000LL);
    if (negative) exponent = -exponent;
  }
  return leading + exponent >= 0;
}

}  // namespace

std::string_view json_type_name(JsonType type) {
  switch (type) {
    case JsonType::null: return "null";
    case JsonType::boolean: return "boolean";
    case JsonType::integer:
    case JsonType::number: return "number";
    case JsonType::string: return "string";
    case JsonType::array: return "array";
    case JsonType::object: return "object";
  }
  return "value";
}

double JsonTree::number(Node n) const {
  if (nodes_[n].type == JsonType::integer) return static_cast<double>(integer(n));
  return std::bit_cast<double>(nodes_[n].payload);
}

// One pass over the text, without recursion: the open containers are a stack of node indices.
class JsonParser {
 public:
  explicit JsonParser(JsonTree& tree) : tree_(tree), text_(tree.text_), end_(tree.text_.size()) {}

  void parse() {
    if (text_.size() >= std::numeric_limits<JsonTree::Node>::max())
      throw JsonSyntaxError(0, "the text is larger than 4 GiB");
    tree_.nodes_.reserve(node_bound());
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;  // byte order mark
    skip_whitespace();
    for (;;) {
      if (value()) {  // a container opened: its first element or member, or its end
        skip_whitespace();
        if (!close_if_at_end()) {
          if (is_object(open_.back())) key();
          continue;
        }
      }
      // A value is complete: the next element or member, the end of its container, or the end.
      for (;;) {
        if (open_.empty()) {
          skip_whitespace();
          if (pos_ != end_) fail(pos_, fmt::format("unexpected {} after the top-level value", describe(pos_)));
          return;
        }
        skip_whitespace();
        if (pos_ < end_ && text_[pos_] == ',') {
          ++pos_;
          skip_whitespace();
          if (is_object(open_.back())) key();
          break;
        }
        if (!close_if_at_end())
          fail(pos_, fmt::format("unexpected {} (expected ',' or '{}')", describe(pos_),
                                 is_object(open_.back()) ? '}' : ']'));
      }
    }
  }

 private:
  [[noreturn]] static void fail(std::size_t offset, const std::string& reason) {
    throw JsonSyntaxError(offset, reason);
  }

  std::string describe(std::size_t at) const {
    if (at >= end_) return "end of text";
    const auto c = static_cast<unsigned char>(text_[at]);
    if (c >= 0x20 && c < 0x7F) return fmt::format("'{}'", static_cast<char>(c));
    return fmt::format("byte 0x{:02X}", c);
  }

  // At most one node per ',' ':' '[' '{' plus the root (each element after a container's
  // first follows a comma, each member's value a colon, each first child an opening bracket),
  // so the nodes are written into memory reserved once: a million-number array never moves.
  std::size_t node_bound() const {
    std::size_t count = 1;
    for (const char c : text_) count += (c == ',') + (c == ':') + (c == '[') + (c == '{');
    return count;
  }

  void skip_whitespace() {
    while (pos_ < end_ && is_whitespace(text_[pos_])) ++pos_;
  }

  bool is_object(JsonTree::Node n) const { return tree_.nodes_[n].type == JsonType::object; }

  JsonTree::Node push(JsonType type, std::uint32_t count, std::uint64_t payload) {
    tree_.nodes_.push_back({type, false, count, payload});
    if (is_container_type(type)) return static_cast<JsonTree::Node>(tree_.nodes_.size() - 1);
    if (!open_.empty()) ++tree_.nodes_[open_.back()].count;
    return static_cast<JsonTree::Node>(tree_.nodes_.size() - 1);
  }
  static bool is_container_type(JsonType type) { return type >= JsonType::array; }

  // A member's key and its colon; pos_ is at the key.
  void key() {
    if (pos_ >= end_ || text_[pos_] != '"')
      fail(pos_, fmt::format("unexpected {} (expected a string key)", describe(pos_)));
    string();
    --tree_.nodes_[open_.back()].count;  // the key and its value are one member, counted by the value
    skip_whitespace();
    if (pos_ >= end_ || text_[pos_] != ':') fail(pos_, fmt::format("unexpected {} (expected ':')", describe(pos_)));
    ++pos_;
    skip_whitespace();
  }

  // The value at pos_. Returns true when it opened a container (now on open_).
  bool value() {
    if (pos_ >= end_) fail(pos_, "unexpected end of text (expected a value)");
    const char c = text_[pos_];
    if (c == '{' || c == '[') {
      if (!open_.empty()) ++tree_.nodes_[open_.back()].count;
      open_.push_back(push(c == '{' ? JsonType::object : JsonType::array, 0, 0));
      ++pos_;
      return true;
    }
    if (c == '"') {
      string();
    } else if (c == '-' || is_digit(c)) {
      number();
    } else if (literal("true")) {
      push(JsonType::boolean, 0, 1);
    } else if (literal("false")) {
      push(JsonType::boolean, 0, 0);
    } else if (literal("null")) {
      push(JsonType::null, 0, 0);
    } else {
      fail(pos_, fmt::format("unexpected {} (expected a value)", describe(pos_)));
    }
    return false;
  }

  bool literal(std::string_view word) {
    if (text_.compare(pos_, word.size(), word) != 0) return false;
    pos_ += word.size();
    return true;
  }

  // At a container's closing bracket: completes it (its end, its keys checked) and returns true.
  bool close_if_at_end() {
    const JsonTree::Node n = open_.back();
    if (pos_ >= end_) fail(pos_, fmt::format("unexpected end of text (expected '{}')", is_object(n) ? '}' : ']'));
    if (text_[pos_] != (is_object(n) ? '}' : ']')) return false;
    ++pos_;
    tree_.nodes_[n].payload = tree_.nodes_.size();
    if (is_object(n)) check_unique_keys(n);
    open_.pop_back();
    return true;
  }

  // RFC 8259 §4: names "SHOULD be unique", and readers differ on which duplicate wins; a scene
  // file with two values for one key is a mistake to report, at the later key.
  void check_unique_keys(JsonTree::Node object) {
    const std::size_t members = tree_.nodes_[object].count;
    if (members < 2) return;
    keys_.clear();  // each key and the offset of its opening quote, in document order
    JsonTree::Node k = tree_.first_child(object);
    for (std::size_t i = 0; i < members; ++i, k = tree_.next(k + 1))
      keys_.emplace_back(tree_.string(k), tree_.string_offset(k));
    std::stable_sort(keys_.begin(), keys_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const std::pair<std::string_view, std::size_t>* repeat = nullptr;  // the first repeat in the text
    for (std::size_t i = 1; i < keys_.size(); ++i)
      if (keys_[i].first == keys_[i - 1].first && (!repeat || keys_[i].second < repeat->second)) repeat = &keys_[i];
    if (repeat) fail(repeat->second, fmt::format("duplicate key \"{}\" in one object", repeat->first.substr(0, 64)));
  }

  // A string at pos_ (its opening quote). Without escapes it stays in the text; from its first
  // escape on it is copied, decoded, into tree_.decoded_.
  void string() {
    const std::size_t quote = pos_;
    const std::size_t begin = pos_ + 1;
    std::size_t read = begin;
    std::string& decoded = tree_.decoded_;
    std::size_t decoded_begin = SIZE_MAX;  // where this string starts in `decoded`, once it has an escape
    std::size_t copied = begin;            // the text before this is in `decoded` (with an escape)
    for (;;) {
      while (read < end_ && plain(text_[read])) ++read;
      if (read >= end_) fail(quote, "unterminated string");
      const auto c = static_cast<unsigned char>(text_[read]);
      if (c == '"') break;
      if (c == '\\') {
        if (read + 1 >= end_) fail(quote, "unterminated string");
        if (decoded_begin == SIZE_MAX) decoded_begin = decoded.size();
        decoded.append(text_, copied, read - copied);
        escape(read, decoded);
        copied = read;
      } else if (c < 0x20) {
        fail(read, fmt::format("control character U+{:04X} in a string (write it as an escape)", c));
      } else {
        const std::size_t length =
            utf8_sequence_length(reinterpret_cast<const unsigned char*>(text_.data()) + read, end_ - read);
        if (length == 0) fail(read, fmt::format("ill-formed UTF-8 (byte 0x{:02X}) in a string", c));
        read += length;
      }
    }
    pos_ = read + 1;
    if (decoded_begin == SIZE_MAX) {
      push(JsonType::string, static_cast<std::uint32_t>(read - begin), begin);
      return;
    }
    decoded.append(text_, copied, read - copied);
    if (decoded.size() > std::numeric_limits<std::uint32_t>::max()) fail(quote, "strings longer than 4 GiB in all");
    push(JsonType::string, static_cast<std::uint32_t>(decoded.size() - decoded_begin),
         (std::uint64_t{decoded_begin} << 32) | begin);
    tree_.nodes_.back().decoded = true;
  }
  static bool plain(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u < 0x80 && c != '"' && c != '\\';
  }

  // The escape at text_[read] (a backslash, not the text's last byte), RFC 8259 §7.
  void escape(std::size_t& read, std::string& out) {
    const std::size_t at = read;
    const char e = text_[read + 1];
    read += 2;
    char simple = 0;
    switch (e) {
      case '"': simple = '"'; break;
      case '\\': simple = '\\'; break;
      case '/': simple = '/'; break;
      case 'b': simple = '\b'; break;
      case 'f': simple = '\f'; break;
      case 'n': simple = '\n'; break;
      case 'r': simple = '\r'; break;
      case 't': simple = '\t'; break;
      case 'u': break;
      default: fail(at, fmt::format("invalid escape '\\{}' in a string", describe_char(e)));
    }
    if (simple != 0) {
      out.push_back(simple);
      return;
    }
    std::uint32_t cp = hex4(read, at);
    if (cp >= 0xDC00 && cp <= 0xDFFF) fail(at, "unpaired surrogate escape in a string");
    if (cp >= 0xD800 && cp <= 0xDBFF) {  // a high surrogate: its low half must follow
      if (read + 1 >= end_ || text_[read] != '\\' || text_[read + 1] != 'u')
        fail(at, "unpaired surrogate escape in a string");
      read += 2;
      const std::uint32_t low = hex4(read, at);
      if (low < 0xDC00 || low > 0xDFFF) fail(at, "unpaired surrogate escape in a string");
      cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }
    char utf8[4];
    out.append(utf8, encode_utf8(cp, utf8));
  }
  std::string describe_char(char c) const {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u < 0x7F ? std::string(1, c) : fmt::format("x{:02X}", u);
  }
  std::uint32_t hex4(std::size_t& read, std::size_t at) {
    std::uint32_t cp = 0;
    for (int i = 0; i < 4; ++i, ++read) {
      const int h = read < end_ ? hex_value(text_[read]) : -1;
      if (h < 0) fail(at, "expected four hexadecimal digits after '\\u'");
      cp = cp * 16 + static_cast<std::uint32_t>(h);
    }
    return cp;
  }

  // A number at pos_, RFC 8259 §6: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
  // Integers within int64 stay exact. Other numbers take Clinger's fast path when it is exact
  // (W. D. Clinger, "How to read floating point numbers accurately", PLDI 1990: a mantissa
  // ≤ 2^53 and a power of ten ≤ 10^22 are both doubles, so one correctly rounded multiply or
  // divide gives the correctly rounded result) and std::from_chars otherwise.
  void number() {
    const std::size_t begin = pos_;
    const bool negative = text_[pos_] == '-';
    if (negative) ++pos_;
    std::uint64_t mantissa = 0;  // the first 19 significant digits
    int significant = 0;
    bool truncated = false;  // a non-zero digit after the 19th
    long long exponent = 0;  // of the last digit kept in mantissa
    const auto take = [&](char c, bool fraction) {
      if (significant < 19) {
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
        significant += mantissa != 0;
        exponent -= fraction;
      } else {
        truncated = truncated || c != '0';
        exponent += !fraction;
      }
    };
    if (pos_ < end_ && text_[pos_] == '0') {
      ++pos_;
    } else if (pos_ < end_ && is_digit(text_[pos_])) {
      for (; pos_ < end_ && is_digit(text_[pos_]); ++pos_) take(text_[pos_], false);
    } else {
      fail(pos_, fmt::format("unexpected {} (expected a digit)", describe(pos_)));
    }
    bool integral = true;
    if (pos_ < end_ && text_[pos_] == '.') {
      ++pos_;
      if (pos_ >= end_ || !is_digit(text_[pos_])) fail(pos_, digit_expected("'.'"));
      for (; pos_ < end_ && is_digit(text_[pos_]); ++pos_) take(text_[pos_], true);
      integral = false;
    }
    if (pos_ < end_ && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      bool negative_exponent = false;
      if (pos_ < end_ && (text_[pos_] == '+' || text_[pos_] == '-')) negative_exponent = text_[pos_++] == '-';
      if (pos_ >= end_ || !is_digit(text_[pos_])) fail(pos_, digit_expected("the exponent"));
      long long e = 0;
      for (; pos_ < end_ && is_digit(text_[pos_]); ++pos_) e = std::min(e * 10 + (text_[pos_] - '0'), 1'000'000'000LL);
      exponent += negative_exponent ? -e : e;
      integral = false;
    }
    constexpr std::uint64_t kMaxNegative = std::uint64_t{1} << 63;
    if (integral && exponent == 0 && (negative ? mantissa <= kMaxNegative : mantissa < kMaxNegative)) {
      const std::int64_t v =
          negative ? static_cast<std::int64_t>(0 - mantissa) : static_cast<std::int64_t>(mantissa);
      push(JsonType::integer, 0, static_cast<std::uint64_t>(v));
      return;
    }
    static constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                              1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    double v;
    if (!truncated && mantissa <= (std::uint64_t{1} << 53) && exponent >= -22 && exponent <= 22) {
      const double m = static_cast<double>(mantissa);
      v = exponent >= 0 ? m * kPowersOfTen[exponent] : m / kPowersOfTen[-exponent];
    } else {
      v = slow_number(begin);
    }
    push(JsonType::number, 0, std::bit_cast<std::uint64_t>(negative ? -v : v));
  }

  // The magnitude of the number token from begin to pos_, correctly rounded by std::from_chars.
  double slow_number(std::size_t begin) const {
    const std::string_view token = text_.substr(begin, pos_ - begin);
    const std::string_view digits = token[0] == '-' ? token.substr(1) : token;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec == std::errc::result_out_of_range) {
      // ±inf or a magnitude below the smallest subnormal: only the first is an error.
      if (magnitude_at_least_one(digits))
        fail(begin, fmt::format("number overflow: {} is beyond a double", token.substr(0, 40)));
      return 0.0;
    }
    if (ec != std::errc() || ptr != digits.data() + digits.size()) fail(begin, "malformed number");  // unreachable
    return v;
  }
  std::string digit_expected(std::string_view after) const {
    return fmt::format("unexpected {} (expected a digit after {})", describe(pos_), after);
  }

  JsonTree& tree_;
  const std::string_view text_;
  const std::size_t end_;
  std::size_t pos_ = 0;
  std::vector<JsonTree::Node> open_;  // the containers not yet closed, innermost last
  std::vector<std::pair<std::string_view, std::size_t>> keys_;  // check_unique_keys' scratch
};

JsonTree::JsonTree(std::string_view text) : text_(text) { JsonParser(*this).parse(); }

}  // namespace prism
