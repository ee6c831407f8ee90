#pragma once
// Tokens of the pbrt-v4 scene format: quoted strings, brackets and bare words (numbers,
// directive names, true/false). `#` starts a comment that runs to the end of the line.
#include <cstddef>
#include <deque>
#include <string>
#include <string_view>

namespace prism::loaders {

enum class PbrtTokenKind { end, string, word, open_bracket, close_bracket };

struct PbrtToken {
  PbrtTokenKind kind = PbrtTokenKind::end;
  // Unquoted and unescaped for strings. A view into the scene text, or into the tokenizer
  // for a string with escapes: valid while the tokenizer is (not a string per token, as a
  // mesh has millions of them).
  std::string_view text;
  int line = 0;
};

class PbrtTokenizer {
 public:
  // `source` names the text in messages (the file name); the text must outlive this.
  PbrtTokenizer(std::string_view text, std::string source);

  const PbrtToken& peek();
  PbrtToken next();
  const std::string& source() const { return source_; }
  int line() const { return line_; }

  // Throws SceneError "<source>:<line>: <message>".
  [[noreturn]] void fail(int line, std::string_view message) const;

 private:
  PbrtToken scan();

  std::string_view text_;
  std::string source_;
  std::deque<std::string> unescaped_;  // strings with escapes, which the text does not hold as they read
  std::size_t pos_ = 0;
  int line_ = 1;
  PbrtToken lookahead_;
  bool has_lookahead_ = false;
};

}  // namespace prism::loaders
