// JSON text written straight into a string: the glTF writer's document.
//
// glTF scenes of a thousand buildings hold millions of nodes; building a DOM
// first (tinygltf's model, nlohmann's json) costs more than the derivation.
// This writer appends as it goes into one growing buffer and keeps only a
// bit per open container ("needs a comma"). Numbers are written in the
// shortest form that reads back to the same double (std::to_chars), so the
// text is deterministic and exact.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace vern {

class JsonText {
 public:
  // prefix: bytes left (zeroed) before the text, for a container header to
  // be filled in later without copying the text (the GLB writer's).
  explicit JsonText(std::size_t prefix = 0);

  // Containers. A key is written before a value inside an object.
  JsonText& open_object();
  JsonText& close_object();
  JsonText& open_array();
  JsonText& close_array();
  JsonText& key(std::string_view name);

  // Values. A non-finite number throws vern::Error (Internal): JSON has no
  // NaN, and the derivation rejects non-finite sizes before writing.
  JsonText& string(std::string_view text);
  JsonText& number(double value);
  JsonText& integer(std::int64_t value);
  JsonText& boolean(bool value);
  JsonText& numbers(std::span<const double> values);  // [a, b, ...]

  // Shorthands for "key": value.
  JsonText& field(std::string_view name, std::string_view text) { return key(name).string(text); }
  JsonText& field(std::string_view name, const char* text) { return key(name).string(text); }
  JsonText& field(std::string_view name, double value) { return key(name).number(value); }
  JsonText& field(std::string_view name, int value) { return key(name).integer(value); }
  JsonText& field(std::string_view name, std::size_t value) {
    return key(name).integer(static_cast<std::int64_t>(value));
  }

  // The text written so far (after the prefix).
  std::string_view text() const { return {buffer_.data() + prefix_, size_ - prefix_}; }
  // The prefix and the text; the writer is empty afterwards.
  std::string take();
  void reserve(std::size_t bytes);
  // Forgets the text written so far (once the caller has kept it), not
  // which containers are open: a long array is written out in pieces.
  void clear_text() { size_ = prefix_; }
  // Bytes the writer holds (what the text has needed at most).
  std::size_t capacity() const { return buffer_.size(); }

 private:
  void before_value();
  void open(char bracket);
  void close(char bracket);
  // Room for n more bytes at the end; returns where they go.
  char* room(std::size_t n);
  void put(char c) { *room(1) = c, ++size_; }
  void put(std::string_view s);
  void number_text(double value);

  std::string buffer_;  // buffer_.size() is the capacity; size_ bytes are used
  std::size_t size_ = 0;
  std::size_t prefix_ = 0;
  // Per open container, one bit: nothing written in it yet. Our documents
  // nest a dozen levels at most; deeper nesting is a bug, caught in open().
  std::uint64_t first_ = 0;
  int depth_ = 0;
  bool after_key_ = false;
};

}  // namespace vern
