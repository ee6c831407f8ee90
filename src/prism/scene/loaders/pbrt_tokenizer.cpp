#include "prism/scene/loaders/pbrt_tokenizer.h"

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism::loaders {

PbrtTokenizer::PbrtTokenizer(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

void PbrtTokenizer::fail(int line, std::string_view message) const {
  throw SceneError(fmt::format("{}:{}: {}", source_, line, message));
}

const PbrtToken& PbrtTokenizer::peek() {
  if (!has_lookahead_) {
    lookahead_ = scan();
    has_lookahead_ = true;
  }
  return lookahead_;
}

PbrtToken PbrtTokenizer::next() {
  if (has_lookahead_) {
    has_lookahead_ = false;
    return std::move(lookahead_);
  }
  return scan();
}

PbrtToken PbrtTokenizer::scan() {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      break;
    }
  }
  PbrtToken token;
  token.line = line_;
  if (pos_ >= text_.size()) return token;
  const char c = text_[pos_];
  if (c == '[' || c == ']') {
    token.kind = c == '[' ? PbrtTokenKind::open_bracket : PbrtTokenKind::close_bracket;
    token.text = text_.substr(pos_, 1);
    ++pos_;
    return token;
  }
  if (c == '"') {
    token.kind = PbrtTokenKind::string;
    ++pos_;
    const std::size_t start = pos_;
    std::string* unescaped = nullptr;  // from the first escape on
    while (true) {
      if (pos_ >= text_.size()) fail(token.line, "unterminated string");
      const char s = text_[pos_++];
      if (s == '"') break;
      if (s == '\n') fail(token.line, "newline inside a string");
      if (s == '\\') {
        if (!unescaped) unescaped = &unescaped_.emplace_back(text_.substr(start, pos_ - 1 - start));
        if (pos_ >= text_.size()) fail(token.line, "unterminated string");
        const char e = text_[pos_++];
        switch (e) {
          case 'n': *unescaped += '\n'; break;
          case 't': *unescaped += '\t'; break;
          case '\\': *unescaped += '\\'; break;
          case '"': *unescaped += '"'; break;
          default: fail(line_, fmt::format("unknown escape '\\{}' in a string", e));
        }
      } else if (unescaped) {
        *unescaped += s;
      }
    }
    token.text = unescaped ? std::string_view(*unescaped) : text_.substr(start, pos_ - 1 - start);
    return token;
  }
  token.kind = PbrtTokenKind::word;
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '"' && text_[pos_] != '[' &&
         text_[pos_] != ']' && text_[pos_] != '#')
    ++pos_;
  token.text = text_.substr(start, pos_ - start);
  return token;
}

}  // namespace prism::loaders
