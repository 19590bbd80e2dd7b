#include "io/json_cursor.hpp"

#include <charconv>
#include <limits>

namespace vern {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

void JsonCursor::skip_space() {
  while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\n' || text_[at_] == '\r' || text_[at_] == '\t'))
    ++at_;
}

char JsonCursor::peek() {
  skip_space();
  if (at_ >= text_.size()) decline();
  return text_[at_];
}

void JsonCursor::expect(char c) {
  if (peek() != c) decline();
  ++at_;
}

void JsonCursor::open_object() {
  expect('{');
  first_.push_back(true);
}

void JsonCursor::open_array() {
  expect('[');
  first_.push_back(true);
}

bool JsonCursor::another(char close) {
  if (first_.empty()) decline();
  const char c = peek();
  if (c == close) {
    ++at_;
    first_.pop_back();
    return false;
  }
  if (first_.back()) {
    first_.back() = false;
    return true;
  }
  if (c != ',') decline();
  ++at_;
  return true;
}

bool JsonCursor::next_key(std::string_view& key) {
  if (!another('}')) return false;
  key = string();
  expect(':');
  return true;
}

bool JsonCursor::next_item() { return another(']'); }

std::string_view JsonCursor::string() {
  expect('"');
  const std::size_t start = at_;
  while (at_ < text_.size() && text_[at_] != '"') {
    const char c = text_[at_];
    // Escapes and other bytes each have rules of their own (UTF-8,
    // surrogate pairs): the full parser applies them.
    if (c < 0x20 || c > 0x7e || c == '\\') decline();
    ++at_;
  }
  if (at_ >= text_.size()) decline();
  return text_.substr(start, at_++ - start);
}

std::string_view JsonCursor::number_literal(bool& integral) {
  skip_space();
  const std::size_t start = at_;
  auto digits = [&] {
    if (at_ >= text_.size() || !is_digit(text_[at_])) decline();
    while (at_ < text_.size() && is_digit(text_[at_])) ++at_;
  };
  if (at_ < text_.size() && text_[at_] == '-') ++at_;
  if (at_ < text_.size() && text_[at_] == '0') ++at_;  // no leading zeros
  else digits();
  integral = true;
  if (at_ < text_.size() && text_[at_] == '.') {
    ++at_;
    digits();
    integral = false;
  }
  if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
    ++at_;
    if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
    digits();
    integral = false;
  }
  return text_.substr(start, at_ - start);
}

double JsonCursor::number() {
  bool integral = false;
  const std::string_view literal = number_literal(integral);
  const char* begin = literal.data();
  const char* end = begin + literal.size();
  // nlohmann::json keeps an integer literal as a 64-bit integer when it
  // fits (so "-0" is the integer 0, and becomes +0.0), else as a double.
  if (integral) {
    if (literal.front() == '-') {
      std::int64_t v = 0;
      if (const auto r = std::from_chars(begin, end, v); r.ec == std::errc() && r.ptr == end)
        return static_cast<double>(v);
    } else {
      std::uint64_t v = 0;
      if (const auto r = std::from_chars(begin, end, v); r.ec == std::errc() && r.ptr == end)
        return static_cast<double>(v);
    }
  }
  double v = 0.0;
  const auto r = std::from_chars(begin, end, v);  // rounds as strtod does
  if (r.ec != std::errc() || r.ptr != end) decline();
  return v;
}

std::uint64_t JsonCursor::unsigned_integer() {
  bool integral = false;
  const std::string_view literal = number_literal(integral);
  if (!integral || literal.front() == '-') decline();
  std::uint64_t v = 0;
  const auto r = std::from_chars(literal.data(), literal.data() + literal.size(), v);
  if (r.ec != std::errc() || r.ptr != literal.data() + literal.size()) decline();
  return v;
}

int JsonCursor::index() {
  const std::uint64_t v = unsigned_integer();
  if (v > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) decline();
  return static_cast<int>(v);
}

bool JsonCursor::boolean() {
  skip_space();
  const std::string_view rest = text_.substr(at_);
  if (rest.starts_with("true")) {
    at_ += 4;
    return true;
  }
  if (rest.starts_with("false")) {
    at_ += 5;
    return false;
  }
  decline();
}

void JsonCursor::finish() {
  skip_space();
  if (!first_.empty() || at_ != text_.size()) decline();
}

}  // namespace vern
