// Tokens of the grammar language.
//
// Rules are line-oriented: the lexer reports the end of a line only outside
// parentheses and braces, so a rule may continue over several lines inside
// `{ }` or `( )` and the parser never sees those newlines.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "graph/error.hpp"

namespace vern {

enum class TokenKind {
  Identifier, Number, String, Directive,  // @start, @scope, @primitives
  Arrow,                                  // --> -> →
  LParen, RParen, LBrace, RBrace, Comma, Colon, Pipe, Tilde, Assign,
  Plus, Minus, Star, Slash, Percent,
  Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, AndAnd, OrOr, Bang,
  Newline, End,
};

const char* token_kind_name(TokenKind k);

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // as written (a string's contents without quotes are in `value`)
  double number = 0.0;
  std::string value;  // String: the unescaped contents; Directive: the name without '@'
  SourceLoc loc;
};

// Splits text into tokens; throws vern::Error (Input) naming file:line:col
// for a character or number it cannot read. The last token is End.
std::vector<Token> tokenize(std::string_view text, const std::string& source_name);

}  // namespace vern
