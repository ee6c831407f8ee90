// JsonTree: RFC 8259 parsing checked three ways. Hand-written cases pin the grammar, the
// decoding and where each error is reported; numbers are compared bit for bit with glibc's
// strtod, an independent correctly rounded reader; and whole documents (the repository's
// scenes, random trees, and random corruptions of them) are compared with nlohmann::json,
// the parser JsonTree replaced, which must agree on what is accepted and on every value.
#include "prism/scene/loaders/json_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "prism/io/read_to_end.h"

namespace prism {
namespace {

// The error a text gives: its offset and reason, or offset SIZE_MAX when it parses.
struct Outcome {
  std::size_t offset = SIZE_MAX;
  std::string reason;
};
Outcome parse_outcome(std::string_view text) {
  try {
    JsonTree tree(text);
    return {};
  } catch (const JsonSyntaxError& e) {
    return {e.offset(), e.what()};
  }
}

// Children of a container, in document order (for an object: keys and values alternate).
std::vector<JsonTree::Node> children(const JsonTree& tree, JsonTree::Node n) {
  std::vector<JsonTree::Node> out;
  const std::size_t count = tree.size(n) * (tree.type(n) == JsonType::object ? 2 : 1);
  JsonTree::Node c = tree.first_child(n);
  for (std::size_t i = 0; i < count; ++i, c = tree.next(c)) out.push_back(c);
  return out;
}

TEST(JsonTree, ReadsEveryKindOfValue) {
  const std::string text =
      " \t\r\n{\"a\": [1, -2, 3.5, true, false, null, \"s\", {}, []], \"b\": {\"c\": \"d\"}, \"e\": -0.0} \n";
  const JsonTree tree(text);
  const JsonTree::Node root = tree.root();
  ASSERT_EQ(tree.type(root), JsonType::object);
  ASSERT_EQ(tree.size(root), 3u);
  const auto members = children(tree, root);
  ASSERT_EQ(members.size(), 6u);
  EXPECT_EQ(tree.string(members[0]), "a");
  EXPECT_EQ(tree.string(members[2]), "b");
  EXPECT_EQ(tree.string(members[4]), "e");
  const auto a = children(tree, members[1]);
  ASSERT_EQ(a.size(), 9u);
  EXPECT_EQ(tree.type(a[0]), JsonType::integer);
  EXPECT_EQ(tree.integer(a[0]), 1);
  EXPECT_EQ(tree.integer(a[1]), -2);
  EXPECT_EQ(tree.type(a[2]), JsonType::number);
  EXPECT_EQ(tree.number(a[2]), 3.5);
  EXPECT_EQ(tree.number(a[1]), -2.0);  // integers read as doubles too
  EXPECT_TRUE(tree.boolean(a[3]));
  EXPECT_FALSE(tree.boolean(a[4]));
  EXPECT_EQ(tree.type(a[5]), JsonType::null);
  EXPECT_EQ(tree.string(a[6]), "s");
  EXPECT_EQ(tree.type(a[7]), JsonType::object);
  EXPECT_EQ(tree.size(a[7]), 0u);
  EXPECT_EQ(tree.type(a[8]), JsonType::array);
  EXPECT_EQ(tree.size(a[8]), 0u);
  const auto b = children(tree, members[3]);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(tree.string(b[0]), "c");
  EXPECT_EQ(tree.string(b[1]), "d");
  EXPECT_TRUE(std::signbit(tree.number(members[5])));
  EXPECT_EQ(json_type_name(JsonType::integer), "number");
  EXPECT_EQ(json_type_name(JsonType::object), "object");
  // A scalar is a whole document too.
  EXPECT_EQ(JsonTree("42").integer(0), 42);
  EXPECT_EQ(JsonTree("\"x\"").string(0), "x");
}

TEST(JsonTree, IntegersStayExactWithinInt64AndBecomeDoublesBeyond) {
  EXPECT_EQ(JsonTree("9223372036854775807").integer(0), INT64_MAX);
  EXPECT_EQ(JsonTree("-9223372036854775808").integer(0), INT64_MIN);
  EXPECT_EQ(JsonTree("9007199254740993").integer(0), 9007199254740993);  // not a double
  const JsonTree beyond("9223372036854775808");
  EXPECT_EQ(beyond.type(0), JsonType::number);
  EXPECT_EQ(beyond.number(0), 9223372036854775808.0);
  const JsonTree huge("123456789012345678901234567890");
  EXPECT_EQ(huge.type(0), JsonType::number);
  EXPECT_EQ(huge.number(0), 123456789012345678901234567890.0);
  EXPECT_EQ(JsonTree("1e2").type(0), JsonType::number);  // an exponent makes a number
  EXPECT_EQ(JsonTree("1.0").type(0), JsonType::number);
}

// glibc's strtod is correctly rounded (IEEE 754 round to nearest); the C locale is the
// program's (nothing in prism calls setlocale).
double strtod_oracle(const std::string& token) { return std::strtod(token.c_str(), nullptr); }

TEST(JsonTree, NumbersAreCorrectlyRoundedLikeStrtod) {
  std::mt19937_64 rng(20261127);
  const auto digit = [&] { return static_cast<char>('0' + rng() % 10); };
  int fast = 0, slow = 0;
  for (int i = 0; i < 200'000; ++i) {
    // Mantissas of 1 to 25 digits around a decimal point, exponents across the double range
    // and beyond (subnormals, underflow to zero), and the Clinger fast path's edges.
    std::string token = rng() % 2 ? "-" : "";
    const int integer_digits = 1 + static_cast<int>(rng() % 20);
    const int fraction_digits = static_cast<int>(rng() % 12);
    token += static_cast<char>('1' + rng() % 9);
    for (int d = 1; d < integer_digits; ++d) token += digit();
    if (fraction_digits > 0 || rng() % 2 == 0) {
      token += '.';
      for (int d = 0; d < std::max(1, fraction_digits); ++d) token += digit();
    }
    const int range = rng() % 4 == 0 ? 330 : 25;
    const int exponent = static_cast<int>(rng() % (2 * range + 1)) - range;
    token += 'e';
    token += std::to_string(exponent);
    const double expected = strtod_oracle(token);
    if (std::isinf(expected)) {
      EXPECT_NE(parse_outcome(token).reason.find("number overflow"), std::string::npos) << token;
      continue;
    }
    const JsonTree tree(token);
    ASSERT_EQ(tree.type(0), JsonType::number) << token;
    const double got = tree.number(0);
    ASSERT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << token << ": " << got << " vs " << expected;
    (std::abs(exponent) <= 22 && integer_digits + fraction_digits <= 15 ? fast : slow) += 1;
  }
  EXPECT_GT(fast, 10'000);  // both paths were exercised
  EXPECT_GT(slow, 10'000);
  // Hand-picked: halfway cases, the largest and smallest doubles, leading zeros.
  for (const std::string token :
       {"9007199254740993.0", "9007199254740992.5e0", "1.7976931348623157e308", "4.9406564584124654e-324",
        "2.4703282292062328e-324", "2.4703282292062327e-324", "0.000000000000000000000000000001", "0.1", "0.3",
        "123456789.123456789e-5", "1e-400", "-1e-400", "0e999999999999", "1e22", "1e23", "8.589973e9"}) {
    const double got = JsonTree(token).number(0), expected = strtod_oracle(token);
    EXPECT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << token;
  }
}

TEST(JsonTree, StringsAreDecoded) {
  const JsonTree tree(R"(["plain", "a\"b\\c\/d\b\f\n\r\t", "\u00e9\u20ac", "\ud83d\ude00", "é€😀", "\u0000z"])");
  const auto s = children(tree, tree.root());
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(tree.string(s[0]), "plain");
  EXPECT_EQ(tree.string(s[1]), "a\"b\\c/d\b\f\n\r\t");
  EXPECT_EQ(tree.string(s[2]), "\xC3\xA9\xE2\x82\xAC");
  EXPECT_EQ(tree.string(s[3]), "\xF0\x9F\x98\x80");
  EXPECT_EQ(tree.string(s[4]), "\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80");
  EXPECT_EQ(tree.string(s[5]), std::string_view("\0z", 2));
  // Offsets of the opening quotes, whatever the decoding.
  EXPECT_EQ(tree.string_offset(s[0]), 1u);
  EXPECT_EQ(tree.string_offset(s[1]), 10u);
}

TEST(JsonTree, ErrorsNameTheOffendingByte) {
  struct Case {
    std::string text;
    std::size_t offset;
    std::string reason;
  };
  const std::vector<Case> cases = {
      {"", 0, "unexpected end of text (expected a value)"},
      {"   ", 3, "unexpected end of text"},
      {"[1,]", 3, "unexpected ']' (expected a value)"},
      {"[,]", 1, "unexpected ','"},
      {"{\"a\" 1}", 5, "expected ':'"},
      {"{\"a\": 1,}", 8, "expected a string key"},
      {"{1: 2}", 1, "expected a string key"},
      {"[1 2]", 3, "expected ',' or ']'"},
      {"{\"a\": 1 \"b\": 2}", 8, "expected ',' or '}'"},
      {"[1, 2", 5, "unexpected end of text (expected ']')"},
      {"[1] x", 4, "after the top-level value"},
      {"tru", 0, "expected a value"},
      {"nul", 0, "expected a value"},
      {"01", 1, "after the top-level value"},
      {"-", 1, "expected a digit"},
      {"-a", 1, "expected a digit"},
      {"+1", 0, "expected a value"},
      {".5", 0, "expected a value"},
      {"1.", 2, "expected a digit after '.'"},
      {"1.e5", 2, "expected a digit after '.'"},
      {"1e", 2, "expected a digit after the exponent"},
      {"1e+", 3, "expected a digit after the exponent"},
      {"[1e999]", 1, "number overflow"},
      {"-1e309", 0, "number overflow"},
      {"\"abc", 0, "unterminated string"},
      {"[\"a\\", 1, "unterminated string"},
      {"\"a\nb\"", 2, "control character U+000A"},
      {"\"\\x\"", 1, "invalid escape '\\x'"},
      {"\"\\u12G4\"", 1, "four hexadecimal digits"},
      {"\"\\ud800\"", 1, "unpaired surrogate"},
      {"\"\\udc00\"", 1, "unpaired surrogate"},
      {"\"\\ud800\\u0041\"", 1, "unpaired surrogate"},
      {"\"\xC0\x80\"", 1, "ill-formed UTF-8 (byte 0xC0)"},          // overlong NUL
      {"\"\xED\xA0\x80\"", 1, "ill-formed UTF-8 (byte 0xED)"},      // a surrogate in UTF-8
      {"\"\xF4\x90\x80\x80\"", 1, "ill-formed UTF-8 (byte 0xF4)"},  // above U+10FFFF
      {"\"\xE2\x82\"", 1, "ill-formed UTF-8"},                      // cut short
      {"\"\xFF\"", 1, "ill-formed UTF-8 (byte 0xFF)"},
      {"\x01", 0, "unexpected byte 0x01"},
      {"{\"a\": 1, \"b\": 2, \"a\": 3}", 17, "duplicate key \"a\""},
      {"{\"k\": {\"x\": 1, \"\\u0078\": 2}}", 15, "duplicate key \"x\""},  // equal once decoded
  };
  for (const Case& c : cases) {
    const Outcome o = parse_outcome(c.text);
    EXPECT_EQ(o.offset, c.offset) << c.text << " -> " << o.reason;
    EXPECT_NE(o.reason.find(c.reason), std::string::npos) << c.text << " -> " << o.reason;
  }
  // Many keys: the later of two equal keys is reported, found by sorting, not pairwise.
  std::string many = "{";
  for (int i = 0; i < 1000; ++i) many += "\"k" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
  const std::size_t repeat = many.size();
  many += "\"k500\": 0}";
  EXPECT_EQ(parse_outcome(many).offset, repeat);
}

TEST(JsonTree, DeepNestingNeedsNoStack) {
  constexpr int kDepth = 1'000'000;
  const std::string deep = std::string(kDepth, '[') + std::string(kDepth, ']');
  const JsonTree tree(deep);
  JsonTree::Node n = tree.root();
  for (int i = 1; i < kDepth; ++i) n = tree.first_child(n);
  EXPECT_EQ(tree.type(n), JsonType::array);
  EXPECT_EQ(tree.size(n), 0u);
  EXPECT_EQ(tree.next(tree.root()), static_cast<JsonTree::Node>(kDepth));
  EXPECT_EQ(parse_outcome(std::string(kDepth, '[')).offset, static_cast<std::size_t>(kDepth));
}

TEST(JsonTree, SkipsAByteOrderMark) {
  EXPECT_EQ(JsonTree("\xEF\xBB\xBF[7]").integer(1), 7);
  EXPECT_EQ(parse_outcome("[7]\xEF\xBB\xBF").offset, 3u);  // only before the value
}

// --- nlohmann::json as an oracle ------------------------------------------------------------

// Whether our node equals nlohmann's value: types, numbers, strings, and members by key.
bool same_value(const JsonTree& tree, JsonTree::Node n, const nlohmann::json& j, std::string& why) {
  const auto differ = [&](const std::string& what) {
    why = what + " at " + j.dump().substr(0, 80);
    return false;
  };
  switch (tree.type(n)) {
    case JsonType::null: return j.is_null() || differ("null");
    case JsonType::boolean: return (j.is_boolean() && j.get<bool>() == tree.boolean(n)) || differ("boolean");
    case JsonType::integer:
      if (!j.is_number_integer()) return differ("integer type");
      if (j.is_number_unsigned())  // nlohmann's type for non-negative integers
        return j.get<std::uint64_t>() == static_cast<std::uint64_t>(tree.integer(n)) || differ("integer");
      return j.get<std::int64_t>() == tree.integer(n) || differ("integer");
    case JsonType::number: {
      if (!j.is_number()) return differ("number type");
      // nlohmann keeps integers up to 2^64 - 1 exact; we hold those above int64 as doubles.
      const double expected = j.get<double>(), got = tree.number(n);
      return std::memcmp(&expected, &got, sizeof got) == 0 || (expected == 0 && got == 0) || differ("number");
    }
    case JsonType::string: return (j.is_string() && j.get<std::string>() == tree.string(n)) || differ("string");
    case JsonType::array: {
      if (!j.is_array() || j.size() != tree.size(n)) return differ("array");
      const auto c = children(tree, n);
      for (std::size_t i = 0; i < c.size(); ++i)
        if (!same_value(tree, c[i], j[i], why)) return false;
      return true;
    }
    case JsonType::object: {
      if (!j.is_object() || j.size() != tree.size(n)) return differ("object");
      const auto c = children(tree, n);
      for (std::size_t i = 0; i < c.size(); i += 2) {
        const auto it = j.find(std::string(tree.string(c[i])));
        if (it == j.end()) return differ("key " + std::string(tree.string(c[i])));
        if (!same_value(tree, c[i + 1], *it, why)) return false;
      }
      return true;
    }
  }
  return differ("type");
}

TEST(JsonTree, ReadsTheRepositorysJsonFilesAsNlohmannDoes) {
  int files = 0;
  for (const char* folder : {"data", "bench/scenes", "tests"}) {
    const std::filesystem::path root = std::filesystem::path(PRISM_SOURCE_DIR) / folder;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      if (entry.path().extension() != ".json" && entry.path().extension() != ".gltf") continue;
      const std::string text = read_file_text(entry.path(), "JSON");
      const JsonTree tree(text);
      std::string why;
      EXPECT_TRUE(same_value(tree, tree.root(), nlohmann::json::parse(text), why)) << entry.path() << ": " << why;
      ++files;
    }
  }
  EXPECT_GT(files, 10);
}

// A random document: nested containers, every scalar kind, strings with escapes and UTF-8.
nlohmann::json random_value(std::mt19937_64& rng, int depth) {
  const int kind = static_cast<int>(rng() % (depth > 4 ? 6 : 8));
  switch (kind) {
    case 0: return nullptr;
    case 1: return rng() % 2 == 0;
    case 2: return static_cast<std::int64_t>(rng()) >> (rng() % 64);
    case 3:  // any exponent from tiny to huge
      return std::ldexp(static_cast<double>(static_cast<std::int64_t>(rng())), static_cast<int>(rng() % 200) - 130);
    case 4: return static_cast<double>(rng() % 2000) / 8.0 - 125.0;
    case 5: {
      static const char* const pieces[] = {"a", "Z", " ", "\"", "\\", "/", "\n", "\t", "\x01",
                                           "é", "€", "😀", "key"};
      std::string s;
      for (int i = static_cast<int>(rng() % 6); i > 0; --i) s += pieces[rng() % std::size(pieces)];
      return s;
    }
    case 6: {
      nlohmann::json a = nlohmann::json::array();
      for (int i = static_cast<int>(rng() % 5); i > 0; --i) a.push_back(random_value(rng, depth + 1));
      return a;
    }
    default: {
      nlohmann::json o = nlohmann::json::object();
      for (int i = static_cast<int>(rng() % 5); i > 0; --i) {
        std::string key = "k";
        key += std::to_string(rng() % 100);
        o[key] = random_value(rng, depth + 1);
      }
      return o;
    }
  }
}

TEST(JsonTree, AgreesWithNlohmannOnRandomDocumentsAndTheirCorruptions) {
  std::mt19937_64 rng(8259);
  int rejected_by_both = 0;
  for (int i = 0; i < 3000; ++i) {
    const nlohmann::json doc = random_value(rng, 0);
    // nlohmann writes "\u00XX" for control characters and UTF-8 as is; half the documents
    // are re-written with everything non-ASCII escaped (surrogate pairs for 😀).
    const std::string text = doc.dump(rng() % 2 ? 1 : -1, ' ', rng() % 2 == 0);
    const JsonTree tree(text);
    std::string why;
    ASSERT_TRUE(same_value(tree, tree.root(), doc, why)) << text << ": " << why;
    // Corruptions: a byte changed, deleted or inserted. Both parsers must accept or reject
    // it alike; JsonTree alone refuses duplicate keys, which a change can create.
    std::string bad = text;
    const std::size_t at = rng() % (bad.size() + 1);
    static const char kBytes[] = "{}[],:\"\\0123456789.eE+-tfnul \xC3\xA9\xFF\x01";
    const char byte = kBytes[rng() % (sizeof kBytes - 1)];
    switch (rng() % 3) {
      case 0: if (at < bad.size()) bad[at] = byte; break;
      case 1: if (at < bad.size()) bad.erase(at, 1); break;
      default: bad.insert(at, 1, byte);
    }
    const Outcome ours = parse_outcome(bad);
    bool nlohmann_accepts = true;
    nlohmann::json theirs;
    try {
      theirs = nlohmann::json::parse(bad);
    } catch (const nlohmann::json::exception&) {
      nlohmann_accepts = false;
    }
    if (ours.offset != SIZE_MAX && nlohmann_accepts) {
      EXPECT_NE(ours.reason.find("duplicate key"), std::string::npos) << bad << ": " << ours.reason;
    } else {
      ASSERT_EQ(ours.offset == SIZE_MAX, nlohmann_accepts) << bad << ": " << ours.reason;
    }
    if (ours.offset == SIZE_MAX) {
      const JsonTree bad_tree(bad);
      EXPECT_TRUE(same_value(bad_tree, bad_tree.root(), theirs, why)) << bad << ": " << why;
    } else if (!nlohmann_accepts) {
      ++rejected_by_both;
    }
  }
  EXPECT_GT(rejected_by_both, 1000);  // the corruptions did break documents
}

}  // namespace
}  // namespace prism
