// Tokens of the grammar language.
//
// Rules are line-oriented: the lexer reports the end of a line only outside
// parentheses and braces, so a rule may continue over several lines inside
// `{ }` or `( )` and the parser never sees those newlines.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>

#include "base/error.hpp"

namespace vern {

enum class TokenKind : std::uint8_t {
  Identifier, Number, String, Directive,  // @start, @scope, @primitives
  Arrow,                                  // --> -> →
  LParen, RParen, LBrace, RBrace, Comma, Colon, Pipe, Tilde, Assign,
  Plus, Minus, Star, Slash, Percent,
  Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, AndAnd, OrOr, Bang,
  Newline, End,
};

const char* token_kind_name(TokenKind k);

// A plain value, cheap to copy: its views are into the text, or (a string
// with escapes, unescaped) into the Lexer that read it, and live as long.
struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // as written (a string's contents without quotes are in `value`)
  double number = 0.0;
  std::string_view value;  // String: the unescaped contents; Directive: the name without '@'
  SourceLoc loc;
};

// Reads text into tokens one at a time, so that a reader holds only the
// few it is looking at: a token took some forty times the memory of the
// text it stands for, and a grammar of a million lines held all of them.
// A UTF-8 byte-order mark at the start of the text is skipped (editors on
// Windows write one). Throws vern::Error (Input) naming file:line:col for a
// character or number it cannot read. After the last token, End, it
// returns End again.
class Lexer {
 public:
  Lexer(std::string_view text, const std::string& source_name);
  Token next();

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  void advance();
  bool starts_with(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
  void skip_space_and_comments();
  double read_number(SourceLoc loc);
  std::string_view read_string(SourceLoc loc);
  TokenKind read_symbol(SourceLoc loc);
  [[noreturn]] void error(SourceLoc loc, const std::string& message, const std::string& hint = {}) const;

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t column_ = 1;
  int depth_ = 0;
  std::deque<std::string> unescaped_;  // strings that held \" or \\, as their tokens' values
  bool started_ = false;                // a token other than End was returned
  TokenKind last_ = TokenKind::Newline;  // the last token returned, once started
};

}  // namespace vern
