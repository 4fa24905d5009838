#pragma once
// The tokens of a scene's text as far as SceneTextCheck looks at them (SceneTextCheck.h).

#include <array>
#include <cctype>
#include <cstring>
#include <string>
#include <string_view>

namespace figment::guard {

// The text's tokens as far as nesting and File names go: words, quoted strings, and the
// braces and brackets that open and close a level. Outside strings '#' starts a comment
// (the header line is one) and commas separate values as spaces do. A word is a view into
// the text (a volume file is thousands of numbers; none is copied); a string is unescaped.
struct Token {
  enum Kind { kWord, kString, kOpen, kClose, kEnd };
  Kind kind = kEnd;
  std::string_view word;
  std::string string;
  int line = 1;
  size_t end = 0;  // where in the text the token ends
  std::string_view text() const { return kind == kString ? std::string_view(string) : word; }
};

class Tokenizer {
 public:
  explicit Tokenizer(const std::string& text) : text_(text) {}

  Token next() {
    skipSpaceAndComments();
    Token token;
    token.line = line_;
    if (at_ >= text_.size()) return token;
    const char c = text_[at_];
    if (c == '{' || c == '[' || c == '}' || c == ']') {
      token.word = std::string_view(text_).substr(at_++, 1);
      token.kind = c == '{' || c == '[' ? Token::kOpen : Token::kClose;
    } else if (c == '"') {
      token.kind = Token::kString;
      token.string = quoted();
    } else {
      token.kind = Token::kWord;
      const size_t start = at_;
      while (at_ < text_.size() && !separates(text_[at_])) ++at_;
      token.word = std::string_view(text_).substr(start, at_ - start);
    }
    token.end = at_;
    return token;
  }

 private:
  // Spaces and the characters that end a word: a table, as each character of an included
  // volume file (tens of kilobytes of numbers) is looked at here. Not '\0': a NUL byte taken
  // for a separator that skipSpaceAndComments() does not skip made next() return empty words
  // forever (a scene with a NUL byte hung figment-view; found by tests/fuzz/fuzz_scene).
  static bool separates(char c) {
    static const std::array<bool, 256> table = [] {
      std::array<bool, 256> t{};
      for (int i = 1; i < 256; ++i) t[i] = std::isspace(i) || std::strchr("{}[]\",#", i) != nullptr;
      return t;
    }();
    return table[static_cast<unsigned char>(c)];
  }

  void skipSpaceAndComments() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '#') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
        line_ += c == '\n';
        ++at_;
      } else {
        return;
      }
    }
  }

  // The string from its opening quote to its closing one; a backslash keeps the next
  // character (\" is a quote in the string, not its end).
  std::string quoted() {
    std::string out;
    for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
      if (text_[at_] == '\\' && at_ + 1 < text_.size()) ++at_;
      line_ += text_[at_] == '\n';
      out += text_[at_];
    }
    ++at_;
    return out;
  }

  const std::string& text_;
  size_t at_ = 0;
  int line_ = 1;
};

}  // namespace figment::guard
