// Reading JSON text token by token, for files whose shape the caller knows.
//
// The GLB reader (plain_glb.hpp) walks a file's JSON with it instead of
// building a document first: a city's examples hold 20,000 nodes, and a
// document of them cost more than everything else reading does. The cursor
// is strict and small on purpose. It reads a subset of JSON whose values
// mean the same to every JSON library, and throws JsonCursor::Declined at
// anything else (string escapes, bytes outside printable ASCII, a number
// no double holds), so its caller can hand the file to a full parser,
// which reads it or says what is wrong with it.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace vern {

class JsonCursor {
 public:
  // Thrown where the text leaves the subset (or is not JSON at all).
  struct Declined {};

  explicit JsonCursor(std::string_view text) : text_(text) {}

  // Objects: open_object(), then next_key() until it returns false (it
  // reads the closing brace), reading each key's value in between.
  void open_object();
  bool next_key(std::string_view& key);

  // Arrays: open_array(), then next_item() before each element until it
  // returns false (it reads the closing bracket).
  void open_array();
  bool next_item();

  // Values. A string has no escapes and only printable ASCII; numbers
  // are as nlohmann::json reads them and tinygltf takes them: an integer
  // literal converted from a 64-bit integer, anything else as strtod
  // rounds it (a value out of double's range declines).
  std::string_view string();
  double number();
  // An integer literal without sign, fraction or exponent that fits 64
  // bits; index() also fits an int (glTF's indices, as tinygltf keeps them).
  std::uint64_t unsigned_integer();
  int index();
  bool boolean();

  // Only white space may follow the document.
  void finish();

 private:
  [[noreturn]] static void decline() { throw Declined{}; }
  void skip_space();
  char peek();  // the next character after white space; declines at the end
  void expect(char c);
  // After a container opens or an element ends: whether another element
  // follows (reading its comma), or the container closes with `close`.
  bool another(char close);
  // The extent of a number literal at the cursor, checked against JSON's
  // grammar; `integral` says whether it has neither fraction nor exponent.
  std::string_view number_literal(bool& integral);

  std::string_view text_;
  std::size_t at_ = 0;
  std::vector<bool> first_;  // per open container: no element read yet
};

}  // namespace vern
