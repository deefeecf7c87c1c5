#include "tokenizer.h"

#include <cfloat>
#include <charconv>
#include <cmath>

namespace cfg {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || isDigit(c); }

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return s;
}

// digits [ '.' digits ] [ (e|E) [+|-] digits ], at least one mantissa digit; no sign.
bool isNumberSyntax(const std::string& s) {
  size_t i = 0, digits = 0;
  while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t expDigits = 0;
    while (i < s.size() && isDigit(s[i])) ++i, ++expDigits;
    if (expDigits == 0) return false;
  }
  return i == s.size();
}

std::string quoteChar(char c) {
  unsigned char u = static_cast<unsigned char>(c);
  if (u >= 0x21 && u < 0x7f) return std::string("'") + c + "'";
  static const char* hex = "0123456789abcdef";
  return std::string("'\\x") + hex[u >> 4] + hex[u & 15] + "'";
}

}  // namespace

bool isNonFiniteWord(const std::string& word) {
  std::string w = lower(word);
  return w == "nan" || w == "inf" || w == "infinity";
}

std::string clip(const std::string& s) {
  if (s.size() <= kQuoteBytes) return s;
  size_t cut = kQuoteBytes;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // inside a character
  return s.substr(0, cut) + "...";
}

std::string quote(const std::string& s) { return "'" + clip(s) + "'"; }

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::End: return "end of file";
    case Tok::String: return "'\"" + clip(t.text) + "\"'";
    default: return quote(t.text);
  }
}

Tokenizer::Tokenizer(const std::string& src, const std::string& file) : src_(src), file_(file) {
  if (src_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;  // UTF-8 byte order mark
}

Token Tokenizer::next() {
  skipSpaceAndComments();
  Token t;
  t.loc = here();
  size_t start = pos_;
  if (pos_ >= src_.size()) return t;
  char c = src_[pos_];
  if (isIdentStart(c)) {
    while (isIdentChar(at())) advance();
    t.kind = Tok::Ident;
    t.text = src_.substr(start, pos_ - start);
  } else if (isDigit(c) || c == '.' ||
             ((c == '+' || c == '-') && (isDigit(at(1)) || at(1) == '.' || isIdentStart(at(1))))) {
    number(t);
  } else if (c == '"') {
    advance();
    while (pos_ < src_.size() && src_[pos_] != '"' && src_[pos_] != '\n') {
      // A file name holding a NUL would be cut short by the file system and print cut short.
      unsigned char u = static_cast<unsigned char>(src_[pos_]);
      if ((u < 0x20 && u != '\t') || u == 0x7f) {
        FileLoc at = t.loc;
        at.column += int(pos_ - start);  // a string is on one line
        throw SceneError(at, "control character " + quoteChar(src_[pos_]) + " in a string");
      }
      advance();
    }
    if (pos_ >= src_.size() || src_[pos_] != '"')
      throw SceneError(t.loc, "unterminated string (a string must end with '\"' on the line it starts)");
    t.kind = Tok::String;
    t.text = src_.substr(start + 1, pos_ - start - 1);
    advance();
  } else if (c == '#') {
    advance();
    size_t word = pos_;
    while (isIdentChar(at())) advance();
    if (src_.compare(word, pos_ - word, "include") != 0)
      throw SceneError(t.loc, pos_ == word ? "unexpected character '#'"
                               : "unknown directive " + quote("#" + src_.substr(word, pos_ - word)));
    t.kind = Tok::Include;
    t.text = "#include";
  } else {
    switch (c) {
      case '{': t.kind = Tok::LBrace; break;
      case '}': t.kind = Tok::RBrace; break;
      case '(': t.kind = Tok::LParen; break;
      case ')': t.kind = Tok::RParen; break;
      case ',': t.kind = Tok::Comma; break;
      case ';': t.kind = Tok::Semi; break;
      case '=': t.kind = Tok::Equals; break;
      default: throw SceneError(t.loc, "unexpected character " + quoteChar(c));
    }
    t.text = std::string(1, c);
    advance();
  }
  t.length = int(pos_ - start);
  return t;
}

void Tokenizer::advance() {
  if (src_[pos_] == '\n') {
    ++line_;
    col_ = 1;
  } else {
    ++col_;
  }
  ++pos_;
}

void Tokenizer::skipSpaceAndComments() {
  while (pos_ < src_.size()) {
    char c = src_[pos_];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
      advance();
    } else if (c == '/' && at(1) == '/') {
      while (pos_ < src_.size() && src_[pos_] != '\n') advance();
    } else if (c == '/' && at(1) == '*') {
      FileLoc open = here();
      advance();
      advance();
      while (pos_ < src_.size() && !(src_[pos_] == '*' && at(1) == '/')) advance();
      if (pos_ >= src_.size()) throw SceneError(open, "unterminated comment: '/*' has no matching '*/'");
      advance();
      advance();
    } else {
      return;
    }
  }
}

// [+|-] then a run of digits, letters, '.', and a sign right after an exponent 'e'.
void Tokenizer::number(Token& t) {
  size_t start = pos_;
  bool sign = src_[pos_] == '+' || src_[pos_] == '-';
  advance();
  bool numeric = isDigit(src_[start + (sign ? 1 : 0)]) || src_[start + (sign ? 1 : 0)] == '.';
  for (;;) {
    char d = at();
    if (isIdentChar(d) || d == '.') {
      advance();
    } else if ((d == '+' || d == '-') && numeric && (src_[pos_ - 1] == 'e' || src_[pos_ - 1] == 'E')) {
      advance();
    } else {
      break;
    }
  }
  t.kind = Tok::Number;
  t.text = src_.substr(start, pos_ - start);
  std::string body = t.text.substr(sign ? 1 : 0);
  if (isNonFiniteWord(body)) throw SceneError(t.loc, quote(t.text) + " is not a finite number");
  if (!numeric) throw SceneError(t.loc, "unexpected character '" + t.text.substr(0, 1) + "'");
  if (!isNumberSyntax(body)) throw SceneError(t.loc, "malformed number " + quote(t.text));
  double v = 0.0;
  std::from_chars_result r = std::from_chars(body.data(), body.data() + body.size(), v);
  if (r.ec != std::errc() || r.ptr != body.data() + body.size() || !std::isfinite(v) || std::fabs(v) > FLT_MAX)
    throw SceneError(t.loc, "number " + quote(t.text) + " is out of range");
  t.number = src_[start] == '-' ? -v : v;
}

}  // namespace cfg
