// The pbrt-v4 tokenizer: words, quoted strings (with and without escapes), brackets,
// comments and line numbers; token texts are views that stay valid while the tokenizer
// lives, also for strings whose escapes it had to rewrite.
#include "prism/scene/loaders/pbrt_tokenizer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prism/core/error.h"
#include "scene/loaders/loader_test_files.h"

namespace prism::loaders {
namespace {

struct Seen {
  PbrtTokenKind kind;
  std::string text;
  int line;
};

TEST(PbrtTokenizer, TokensAndTheirTextsStayValidWhileTheTokenizerLives) {
  const std::string text =
      "Shape \"trianglemesh\" # a comment \"not a string\"\n"
      "  \"point3 P\" [ 0 1.5 -2e3 ] \"string name\" \"say \\\"hi\\\"\\n\\tand \\\\ bye\"\n"
      "\"bool on\" true \"string plain\" \"no escapes\"";
  PbrtTokenizer tokens(text, "test.pbrt");
  std::vector<PbrtToken> all;  // kept: their views must survive the tokens scanned after them
  while (tokens.peek().kind != PbrtTokenKind::end) all.push_back(tokens.next());
  const std::vector<Seen> expected = {
      {PbrtTokenKind::word, "Shape", 1},          {PbrtTokenKind::string, "trianglemesh", 1},
      {PbrtTokenKind::string, "point3 P", 2},     {PbrtTokenKind::open_bracket, "[", 2},
      {PbrtTokenKind::word, "0", 2},              {PbrtTokenKind::word, "1.5", 2},
      {PbrtTokenKind::word, "-2e3", 2},           {PbrtTokenKind::close_bracket, "]", 2},
      {PbrtTokenKind::string, "string name", 2},  {PbrtTokenKind::string, "say \"hi\"\n\tand \\ bye", 2},
      {PbrtTokenKind::string, "bool on", 3},      {PbrtTokenKind::word, "true", 3},
      {PbrtTokenKind::string, "string plain", 3}, {PbrtTokenKind::string, "no escapes", 3}};
  ASSERT_EQ(all.size(), expected.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(all[i].kind, expected[i].kind) << i;
    EXPECT_EQ(all[i].text, expected[i].text) << i;
    EXPECT_EQ(all[i].line, expected[i].line) << i;
  }
}

TEST(PbrtTokenizer, MalformedStringsAreErrorsWithTheirLine) {
  const auto error = [](const std::string& text) {
    return test::error_of<SceneError>([&] {
      PbrtTokenizer tokens(text, "bad.pbrt");
      while (tokens.next().kind != PbrtTokenKind::end) {
      }
    });
  };
  EXPECT_NE(error("Shape\n\"open").find("bad.pbrt:2: unterminated string"), std::string::npos);
  EXPECT_NE(error("\"a\nb\"").find("bad.pbrt:1: newline inside a string"), std::string::npos);
  EXPECT_NE(error("\"a\\q\"").find("unknown escape '\\q'"), std::string::npos);
  EXPECT_NE(error("\"ends in \\").find("unterminated string"), std::string::npos);
}

}  // namespace
}  // namespace prism::loaders
