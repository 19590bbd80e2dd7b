#include "graph/lexer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "base/decimal_range.hpp"
#include "base/utf8.hpp"

namespace vern {

const char* token_kind_name(TokenKind k) {
  switch (k) {
    case TokenKind::Identifier: return "a name";
    case TokenKind::Number: return "a number";
    case TokenKind::String: return "a string";
    case TokenKind::Directive: return "a directive";
    case TokenKind::Arrow: return "'-->'";
    case TokenKind::LParen: return "'('";
    case TokenKind::RParen: return "')'";
    case TokenKind::LBrace: return "'{'";
    case TokenKind::RBrace: return "'}'";
    case TokenKind::Comma: return "','";
    case TokenKind::Colon: return "':'";
    case TokenKind::Pipe: return "'|'";
    case TokenKind::Tilde: return "'~'";
    case TokenKind::Assign: return "'='";
    case TokenKind::Plus: return "'+'";
    case TokenKind::Minus: return "'-'";
    case TokenKind::Star: return "'*'";
    case TokenKind::Slash: return "'/'";
    case TokenKind::Percent: return "'%'";
    case TokenKind::Equal: return "'=='";
    case TokenKind::NotEqual: return "'!='";
    case TokenKind::Less: return "'<'";
    case TokenKind::LessEqual: return "'<='";
    case TokenKind::Greater: return "'>'";
    case TokenKind::GreaterEqual: return "'>='";
    case TokenKind::AndAnd: return "'&&'";
    case TokenKind::OrOr: return "'||'";
    case TokenKind::Bang: return "'!'";
    case TokenKind::Newline: return "the end of the line";
    case TokenKind::End: return "the end of the file";
  }
  return "?";
}

namespace {

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }

}  // namespace

Lexer::Lexer(std::string_view text, const std::string& source_name) : text_(text), source_(source_name) {
  // A byte-order mark says only that the file is UTF-8, which it must be.
  if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;
}

Token Lexer::next() {
  if (started_ && last_ == TokenKind::End) return {TokenKind::End, {}, 0, {}, {line_, column_}};
  while (true) {
    skip_space_and_comments();
    if (at_end()) {
      // The last line needs no newline: the parser sees one all the same.
      last_ = started_ && last_ != TokenKind::Newline ? TokenKind::Newline : TokenKind::End;
      started_ = true;
      return {last_, {}, 0, {}, {line_, column_}};
    }
    const SourceLoc loc{line_, column_};
    const std::size_t start = pos_;
    const char c = text_[pos_];
    if (c == '\n') {
      advance();
      if (depth_ == 0 && started_ && last_ != TokenKind::Newline) {
        last_ = TokenKind::Newline;
        return {TokenKind::Newline, text_.substr(start, 1), 0, {}, loc};
      }
      continue;
    }
    Token t;
    t.loc = loc;
    if (is_ident_start(c)) {
      while (!at_end() && is_ident_char(text_[pos_])) advance();
      t.kind = TokenKind::Identifier;
    } else if (is_digit(c) || (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))) {
      t.kind = TokenKind::Number;
      t.number = read_number(loc);
    } else if (c == '"') {
      t.kind = TokenKind::String;
      t.value = read_string(loc);
    } else if (c == '@') {
      advance();
      while (!at_end() && is_ident_char(text_[pos_])) advance();
      t.kind = TokenKind::Directive;
      t.value = text_.substr(start + 1, pos_ - start - 1);
      if (t.value.empty())
        error(loc, "'@' must start a directive (@start, @scope or @primitives)",
              "write @scope 12, 8, 9 (no space after '@')");
    } else {
      t.kind = read_symbol(loc);
    }
    t.text = text_.substr(start, pos_ - start);
    started_ = true;
    last_ = t.kind;
    return t;
  }
}

void Lexer::advance() {
  const char c = text_[pos_++];
  if (c == '\n') {
    ++line_;
    column_ = 1;
  } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
    ++column_;  // columns count characters, not UTF-8 continuation bytes
  }
}

void Lexer::skip_space_and_comments() {
  while (!at_end()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      advance();
    } else if (c == '#' || starts_with("//")) {
      while (!at_end() && text_[pos_] != '\n') advance();
    } else if (c == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') {
      advance();  // an explicit line continuation
      advance();
    } else {
      return;
    }
  }
}

double Lexer::read_number(SourceLoc loc) {
  const std::size_t start = pos_;
  while (!at_end() && (is_digit(text_[pos_]) || text_[pos_] == '.')) advance();
  if (!at_end() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
    std::size_t look = pos_ + 1;
    const bool sign = look < text_.size() && (text_[look] == '+' || text_[look] == '-');
    if (sign) ++look;
    if (look < text_.size() && is_digit(text_[look])) {
      while (pos_ < look) advance();
      while (!at_end() && is_digit(text_[pos_])) advance();
    } else if (sign || look == text_.size() || !is_ident_char(text_[look])) {
      // "1e", "1e+": not a number that runs into a name (2e3x, 2each).
      error(loc,
            "the number " + std::string(text_.substr(start, look - start)) + " has no digits after its exponent 'e'",
            "write the exponent, as in 1e3 or 2.5e-3 (or 2 * e, for a name e)");
    }
  }
  const std::string_view s = text_.substr(start, pos_ - start);
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && decimal_underflows(s))
    error(loc,
          "the number " + std::string(s) +
              " is too small: nearer to zero than any double (4.9e-324), it would read as 0",
          "write 0 if zero is meant; sizes are in metres, so 1e-9 is already a nanometre");
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(v)))
    error(loc, "the number " + std::string(s) + " is too large", "numbers must fit a double (about 1e308)");
  if (ec != std::errc() || end != s.data() + s.size())
    error(loc, "cannot read the number '" + std::string(s) + "'", "write numbers like 2, 0.5 or 1e-3");
  if (!at_end() && is_ident_start(text_[pos_]))
    error({line_, column_}, "a number runs into a name here", "put an operator between them, e.g. 2 * n");
  return v;
}

std::string_view Lexer::read_string(SourceLoc loc) {
  advance();  // opening quote
  const std::size_t start = pos_;
  std::string value;  // once an escape is seen: the contents so far, unescaped
  bool escaped = false;
  while (true) {
    if (at_end() || text_[pos_] == '\n') error(loc, "this string has no closing '\"'", "end it on the same line");
    const char c = text_[pos_];
    if (c == '"') {
      const std::string_view contents = escaped ? std::string_view(value) : text_.substr(start, pos_ - start);
      advance();
      // Strings name primitives and files: text, never stray bytes.
      if (const std::size_t bad = invalid_utf8_offset(contents); bad != std::string::npos)
        error(loc, "this string is not UTF-8 text", "save the grammar file as UTF-8");
      if (!escaped) return contents;
      return unescaped_.emplace_back(std::move(value));
    }
    if (c == '\\' && pos_ + 1 < text_.size() && (text_[pos_ + 1] == '"' || text_[pos_ + 1] == '\\')) {
      if (!escaped) value.assign(text_.substr(start, pos_ - start));
      escaped = true;
      advance();
      value += text_[pos_];
      advance();
      continue;
    }
    if (escaped) value += c;
    advance();
  }
}

TokenKind Lexer::read_symbol(SourceLoc loc) {
  struct Symbol {
    std::string_view text;
    TokenKind kind;
  };
  // Longest first, so "-->" wins over "->" over "-", and "<=" over "<".
  static constexpr Symbol symbols[] = {
      {"-->", TokenKind::Arrow},       {"->", TokenKind::Arrow},        {"\xE2\x86\x92", TokenKind::Arrow},
      {"\xE2\x89\xA4", TokenKind::LessEqual}, {"\xE2\x89\xA5", TokenKind::GreaterEqual},
      {"\xE2\x89\xA0", TokenKind::NotEqual},
      {"==", TokenKind::Equal},        {"!=", TokenKind::NotEqual},     {"<=", TokenKind::LessEqual},
      {">=", TokenKind::GreaterEqual}, {"&&", TokenKind::AndAnd},       {"||", TokenKind::OrOr},
      {"(", TokenKind::LParen},        {")", TokenKind::RParen},        {"{", TokenKind::LBrace},
      {"}", TokenKind::RBrace},        {",", TokenKind::Comma},         {":", TokenKind::Colon},
      {"|", TokenKind::Pipe},          {"~", TokenKind::Tilde},         {"=", TokenKind::Assign},
      {"+", TokenKind::Plus},          {"-", TokenKind::Minus},         {"*", TokenKind::Star},
      {"/", TokenKind::Slash},         {"%", TokenKind::Percent},       {"<", TokenKind::Less},
      {">", TokenKind::Greater},       {"!", TokenKind::Bang},
  };
  for (const auto& s : symbols) {
    if (starts_with(s.text)) {
      for (std::size_t i = 0; i < s.text.size(); ++i) advance();
      if (s.kind == TokenKind::LParen || s.kind == TokenKind::LBrace) ++depth_;
      if ((s.kind == TokenKind::RParen || s.kind == TokenKind::RBrace) && depth_ > 0) --depth_;
      return s.kind;
    }
  }
  const unsigned char c = static_cast<unsigned char>(text_[pos_]);
  // A whole UTF-8 character is shown as itself ('≈'), anything else as a byte.
  std::size_t length = c < 0x80 ? 1 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
  if (pos_ + length > text_.size() || invalid_utf8_offset(text_.substr(pos_, length)) != std::string_view::npos)
    length = 0;
  std::string shown;
  if (c < 0x20 || c == 0x7F || length == 0) {
    char byte[16];
    std::snprintf(byte, sizeof byte, "byte 0x%02X", c);
    shown = byte;
  } else {
    shown = "'" + std::string(text_.substr(pos_, length)) + "'";
  }
  if (c >= 0x80 && length > 0) {
    // Its code point too: many characters show as nothing, or as a space.
    char32_t point = c & (0x7Fu >> length);
    for (std::size_t i = 1; i < length; ++i)
      point = (point << 6) | (static_cast<unsigned char>(text_[pos_ + i]) & 0x3Fu);
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(point));
    if (point == 0xFEFF)
      error(loc, std::string("unexpected byte-order mark (") + code + ") after the start of the file",
            "delete it: a byte-order mark may stand only at the very start of a file");
    shown += std::string(" (") + code + ")";
  }
  error(loc, "unexpected character " + shown,
        c == 0 || length == 0 ? "this does not look like a UTF-8 text file: give a grammar (.grm) text file"
                              : "grammar files use ASCII operators (and → ≤ ≥ ≠); quote paths: @primitives \"a.obj\"");
}

void Lexer::error(SourceLoc loc, const std::string& message, const std::string& hint) const {
  fail(ErrorKind::Input, source_, loc, message, hint);
}

}  // namespace vern
