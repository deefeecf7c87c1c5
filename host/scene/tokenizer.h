// Tokenizer of the .cfg scene format (docs/scene-format.md): pbrt style, a FileLoc on every
// token. Used by parser.cpp. Lexical errors throw SceneError.
#pragma once

#include "scene.h"

#include <string>

namespace cfg {

enum class Tok { End, Ident, Number, String, Include, LBrace, RBrace, LParen, RParen, Comma, Semi, Equals };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // identifier, number spelling, or string contents (no quotes)
  double number = 0.0;
  FileLoc loc;
  int length = 0;  // characters the token spans in the source (all on one line)
};

// "nan", "inf", "infinity" in any case: words that must not pass for numbers or names.
bool isNonFiniteWord(const std::string& word);

// Longest scene text a message quotes, in bytes: a message stays one short line whatever the input.
constexpr size_t kQuoteBytes = 40;

// s cut to kQuoteBytes at a UTF-8 character boundary, followed by "..." when cut.
std::string clip(const std::string& s);

// s clipped and in single quotes: how messages quote a word or value from a scene.
std::string quote(const std::string& s);

// How a token is named in messages: 'x', '"text"' (clipped) or end of file.
std::string describe(const Token& t);

class Tokenizer {
 public:
  // src must outlive the tokenizer.
  Tokenizer(const std::string& src, const std::string& file);
  Token next();

 private:
  FileLoc here() const { return FileLoc{file_, line_, col_}; }
  char at(size_t k = 0) const { return pos_ + k < src_.size() ? src_[pos_ + k] : '\0'; }
  void advance();
  void skipSpaceAndComments();
  void number(Token& t);

  const std::string& src_;
  std::string file_;
  size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

}  // namespace cfg
