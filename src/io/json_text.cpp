#include "io/json_text.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

#include "base/error.hpp"

namespace vern {

JsonText::JsonText(std::size_t prefix) : buffer_(std::max<std::size_t>(prefix, 256), '\0'), size_(prefix), prefix_(prefix) {}

char* JsonText::room(std::size_t n) {
  if (size_ + n > buffer_.size()) buffer_.resize(std::max(buffer_.size() * 2, size_ + n));
  return buffer_.data() + size_;
}

void JsonText::put(std::string_view s) {
  std::memcpy(room(s.size()), s.data(), s.size());
  size_ += s.size();
}

void JsonText::reserve(std::size_t bytes) {
  if (size_ + bytes > buffer_.size()) buffer_.resize(size_ + bytes);
}

std::string JsonText::take() {
  buffer_.resize(size_);
  size_ = prefix_ = 0;
  return std::move(buffer_);
}

void JsonText::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (depth_ > 0) {
    const std::uint64_t bit = std::uint64_t{1} << (depth_ - 1);
    if ((first_ & bit) == 0) put(',');
    first_ &= ~bit;
  }
}

void JsonText::open(char bracket) {
  before_value();
  if (depth_ == 64) throw Error(ErrorKind::Internal, "error: JSON nested deeper than 64 levels");
  put(bracket);
  first_ |= std::uint64_t{1} << depth_;
  ++depth_;
}

void JsonText::close(char bracket) {
  if (depth_ == 0) throw Error(ErrorKind::Internal, "error: JSON container closed that was never opened");
  --depth_;
  put(bracket);
}

JsonText& JsonText::open_object() {
  open('{');
  return *this;
}

JsonText& JsonText::close_object() {
  close('}');
  return *this;
}

JsonText& JsonText::open_array() {
  open('[');
  return *this;
}

JsonText& JsonText::close_array() {
  close(']');
  return *this;
}

JsonText& JsonText::key(std::string_view name) {
  string(name);
  put(':');
  after_key_ = true;
  return *this;
}

JsonText& JsonText::string(std::string_view s) {
  before_value();
  put('"');
  // Runs of characters that need no escape are copied whole: labels rarely
  // hold any that do.
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<unsigned char>(s[i]);
    if (u >= 0x20 && s[i] != '"' && s[i] != '\\') continue;
    put(s.substr(run, i - run));
    run = i + 1;
    if (u >= 0x20) {
      put('\\');
      put(s[i]);
    } else {
      // Control characters must be escaped; bytes >= 0x80 pass through
      // (labels are UTF-8, which JSON carries as it is).
      static constexpr char kHex[] = "0123456789abcdef";
      put("\\u00");
      put(kHex[u >> 4]);
      put(kHex[u & 15]);
    }
  }
  put(s.substr(run));
  put('"');
  return *this;
}

void JsonText::number_text(double value) {
  if (!std::isfinite(value)) {
    throw Error(ErrorKind::Internal, "error: a non-finite number reached the glTF writer");
  }
  char* at = room(32);
  // Whole numbers (0, 1 and -1 fill most of a scope matrix) print as
  // integers: quicker, and the same value; -0 becomes 0.
  if (std::abs(value) < 1e15 && value == std::trunc(value)) {
    size_ = static_cast<std::size_t>(std::to_chars(at, at + 32, static_cast<std::int64_t>(value)).ptr -
                                     buffer_.data());
    return;
  }
  size_ = static_cast<std::size_t>(std::to_chars(at, at + 32, value).ptr - buffer_.data());
}

JsonText& JsonText::number(double value) {
  before_value();
  number_text(value);
  return *this;
}

JsonText& JsonText::integer(std::int64_t value) {
  before_value();
  char* at = room(24);
  size_ = static_cast<std::size_t>(std::to_chars(at, at + 24, value).ptr - buffer_.data());
  return *this;
}

JsonText& JsonText::boolean(bool value) {
  before_value();
  put(value ? "true" : "false");
  return *this;
}

JsonText& JsonText::numbers(std::span<const double> values) {
  open_array();
  if (!values.empty()) {
    number_text(values[0]);
    for (std::size_t i = 1; i < values.size(); ++i) {
      put(',');
      number_text(values[i]);
    }
    first_ &= ~(std::uint64_t{1} << (depth_ - 1));
  }
  return close_array();
}

}  // namespace vern
